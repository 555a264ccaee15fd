// ISG-CSV (see isg_csv.hpp).
#include "volcomp/datasets/isg_csv.hpp"

#include <map>
#include <sstream>
#include <utility>

#include "iso230_text.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {
namespace {

using iso230_text::Content;
using iso230_text::Upper;
using iso230_text::Words;

bool IsArgumentName(const std::string& w) {
  return w.size() == 1 && std::string("XYZABCUVW").find(w[0]) != std::string::npos;
}

struct Block {
  std::size_t header_line = 0;
  std::vector<std::string> columns;
  std::size_t arguments = 0;  // the first columns that are arguments
  std::vector<std::vector<double>> rows;
  std::size_t last_line = 0;
};

Expected<Iso230Parameter> ParameterOfColumn(const Block& b,
                                            std::size_t c,
                                            const std::string& source) {
  Iso230Parameter p;
  p.name = b.columns[c];
  p.line = b.header_line;
  if (b.arguments == 0) {
    if (b.rows.size() != 1) {
      return Fail(Error::kInputInvalid,
                  source + ":" + std::to_string(b.header_line) +
                      ": a block without an argument column holds one row of values, this one " +
                      std::to_string(b.rows.size()));
    }
    p.values = {b.rows[0][c]};
    return p;
  }
  p.tabulated = true;
  p.argument = b.columns[0];
  for (const auto& row : b.rows) {
    p.arguments.push_back(row[0]);
    p.values.push_back(row[c]);
  }
  return p;
}

}  // namespace

Expected<Iso230Set> ParseIsgCsv(const std::string& text, const std::string& source) {
  Iso230Set set;
  set.source = source;
  std::vector<Block> blocks(1);
  std::istringstream in(text);
  std::size_t line_no = 0;
  const auto bad = [&](std::size_t line, const std::string& m) {
    return Fail(Error::kInputInvalid, source + ":" + std::to_string(line) + ": " + m);
  };
  for (std::string raw; std::getline(in, raw);) {
    ++line_no;
    const std::string line = Content(raw);
    if (line.empty()) continue;
    if (line == "#") {
      if (!blocks.back().columns.empty()) blocks.emplace_back();
      continue;
    }
    Block& b = blocks.back();
    const std::vector<std::string> words = Words(line);
    if (b.columns.empty()) {
      b.header_line = line_no;
      for (const std::string& w : words) b.columns.push_back(Upper(w));
      while (b.arguments < b.columns.size() && IsArgumentName(b.columns[b.arguments])) {
        ++b.arguments;
      }
      if (b.arguments > 1) {
        return bad(line_no, "a block over several arguments (" + b.columns[0] + ", " +
                                b.columns[1] +
                                ") is a volumetric grid, not a 21-parameter set: each "
                                "component error depends on its own axis only");
      }
      if (b.arguments == b.columns.size()) {
        return bad(line_no, "the header names no parameter after the argument " + b.columns[0]);
      }
      for (std::size_t c = b.arguments; c < b.columns.size(); ++c) {
        if (IsArgumentName(b.columns[c])) {
          return bad(line_no, "argument column " + b.columns[c] +
                                  " after the parameters: arguments come first");
        }
      }
      continue;
    }
    if (words.size() != b.columns.size()) {
      return bad(line_no, std::to_string(words.size()) + " fields, the header (line " +
                              std::to_string(b.header_line) + ") has " +
                              std::to_string(b.columns.size()));
    }
    std::vector<double> row;
    for (std::size_t c = 0; c < words.size(); ++c) {
      const auto v = tools::ParseDouble(words[c]);
      if (!v) return bad(line_no, b.columns[c] + ": \"" + words[c] + "\" is not a number");
      row.push_back(*v);
    }
    b.rows.push_back(std::move(row));
    b.last_line = line_no;
  }
  if (blocks.back().columns.empty()) blocks.pop_back();
  if (blocks.empty()) return Fail(Error::kInputInvalid, source + ": no header line");
  for (const Block& b : blocks) {
    if (b.rows.empty()) return bad(b.header_line, "the block has a header and no rows");
    for (std::size_t c = b.arguments; c < b.columns.size(); ++c) {
      VOLCOMP_TRY_ASSIGN(Iso230Parameter p, ParameterOfColumn(b, c, source));
      set.parameters.push_back(std::move(p));
    }
  }
  VOLCOMP_TRY(CheckIso230Set(set));
  return set;
}

Expected<std::string> FormatIsgCsv(const Iso230Set& set, const std::vector<std::string>& header) {
  using iso230_text::Fixed;
  std::map<std::string, std::vector<const Iso230Parameter*>> by_argument;
  std::vector<std::string> order;
  std::vector<const Iso230Parameter*> single;
  for (const Iso230Parameter& p : set.parameters) {
    if (!p.tabulated) {
      single.push_back(&p);
      continue;
    }
    auto& group = by_argument[p.argument];
    if (group.empty()) order.push_back(p.argument);
    if (!group.empty() && group.front()->arguments != p.arguments) {
      return Fail(Error::kInvalidArgument, p.name + " has other " + p.argument + " rows than " +
                                               group.front()->name + ": one block per argument");
    }
    group.push_back(&p);
  }
  std::string out = iso230_text::CommentLines(header);
  bool first = true;
  for (const std::string& a : order) {
    if (!first) out += "#\n";
    first = false;
    const auto& group = by_argument[a];
    out += a;
    for (const Iso230Parameter* p : group) out += " " + p->name;
    out += "\n";
    for (std::size_t i = 0; i < group.front()->arguments.size(); ++i) {
      out += Fixed(group.front()->arguments[i], iso230_text::kArgumentDecimals);
      for (const Iso230Parameter* p : group) {
        out += " " + Fixed(p->values[i], iso230_text::kValueDecimals);
      }
      out += "\n";
    }
  }
  if (!single.empty()) {
    if (!first) out += "#\n";
    std::string names, values;
    for (const Iso230Parameter* p : single) {
      names += (names.empty() ? "" : " ") + p->name;
      values += (values.empty() ? "" : " ") + Fixed(p->values.front(), iso230_text::kValueDecimals);
    }
    out += names + "\n" + values + "\n";
  }
  return out;
}

}  // namespace volcomp::datasets
