// The Etalon exchange format (see etalon_exchange.hpp).
#include "volcomp/datasets/etalon_exchange.hpp"

#include <sstream>
#include <utility>

#include "iso230_text.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {
namespace {

using iso230_text::Content;
using iso230_text::Upper;
using iso230_text::Words;

class EtalonReader {
 public:
  explicit EtalonReader(std::string source) { set_.source = std::move(source); }

  Outcome Line(const std::string& raw, std::size_t line_no) {
    line_ = line_no;
    const std::string text = Content(raw);
    if (text.empty()) return Outcome::Ok();
    if (in_grid_) return GridWords(text);
    if (text.front() == '[') return Block(text);
    if (!open_) return Bad("\"" + text + "\" is outside a [PARAMETER] block");
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) return Bad("expected `VALUE = ...` or `Gridpoints = {`");
    const std::string key = Upper(Trim(text.substr(0, eq)));
    const std::string value = Trim(text.substr(eq + 1));
    Iso230Parameter& p = set_.parameters.back();
    if (has_value_ || p.tabulated) {
      return Bad(p.name + " has a value already (one VALUE or one Gridpoints per block)");
    }
    if (key == "VALUE") {
      const auto v = tools::ParseDouble(value);
      if (!v) return Bad("VALUE: \"" + value + "\" is not a number");
      p.values.push_back(*v);
      has_value_ = true;
      return Outcome::Ok();
    }
    if (key == "GRIDPOINTS") {
      if (value.empty() || value.front() != '{') return Bad("Gridpoints must start with {");
      p.tabulated = true;
      p.argument = p.name.size() == 3 && p.name[0] == 'E' ? std::string(1, p.name[2]) : "";
      in_grid_ = true;
      grid_line_ = line_no;
      return GridWords(value.substr(1));
    }
    return Bad("unknown key \"" + Trim(text.substr(0, eq)) + "\" (VALUE or Gridpoints)");
  }

  Expected<Iso230Set> Finish() {
    if (in_grid_) {
      line_ = grid_line_;
      return Bad("the Gridpoints of " + set_.parameters.back().name + " are not closed by }");
    }
    VOLCOMP_TRY(CloseBlock());
    if (set_.parameters.empty()) {
      return Fail(Error::kInputInvalid, set_.source + ": no [PARAMETER] block");
    }
    VOLCOMP_TRY(CheckIso230Set(set_));
    return std::move(set_);
  }

 private:
  Unexpected<Failure> Bad(const std::string& message) const {
    return Fail(Error::kInputInvalid, set_.source + ":" + std::to_string(line_) + ": " + message);
  }

  Outcome CloseBlock() {
    if (!open_) return Outcome::Ok();
    const Iso230Parameter& p = set_.parameters.back();
    if (!has_value_ && !p.tabulated) {
      line_ = p.line;
      return Bad("[" + p.name + "] has neither VALUE nor Gridpoints");
    }
    if (p.tabulated && p.values.empty()) {
      line_ = p.line;
      return Bad("the Gridpoints of " + p.name + " are empty");
    }
    return Outcome::Ok();
  }

  Outcome Block(const std::string& text) {
    VOLCOMP_TRY(CloseBlock());
    if (text.back() != ']') return Bad("\"" + text + "\": a block name ends with ]");
    Iso230Parameter p;
    p.name = Upper(Trim(text.substr(1, text.size() - 2)));
    p.line = line_;
    set_.parameters.push_back(std::move(p));
    open_ = true;
    has_value_ = false;
    return Outcome::Ok();
  }

  // Numbers of a Gridpoints list, up to its closing brace.
  Outcome GridWords(std::string text) {
    Iso230Parameter& p = set_.parameters.back();
    const std::size_t close = text.find('}');
    const bool closes = close != std::string::npos;
    if (closes) {
      if (!Trim(text.substr(close + 1)).empty()) return Bad("text after }");
      text = text.substr(0, close);
    }
    for (const std::string& w : Words(text)) {
      const auto v = tools::ParseDouble(w);
      if (!v) return Bad(p.name + ": \"" + w + "\" is not a number");
      (pending_ ? p.values : p.arguments).push_back(*v);
      pending_ = !pending_;
    }
    if (closes) {
      if (pending_) {
        return Bad("the Gridpoints of " + p.name +
                   " end with an argument without its value (pairs `argument value`)");
      }
      in_grid_ = false;
    }
    return Outcome::Ok();
  }

  Iso230Set set_;
  std::size_t line_ = 0;
  std::size_t grid_line_ = 0;
  bool open_ = false;
  bool has_value_ = false;
  bool in_grid_ = false;
  bool pending_ = false;  // an argument read, its value not yet
};

}  // namespace

Expected<Iso230Set> ParseEtalonExchange(const std::string& text, const std::string& source) {
  EtalonReader reader(source);
  std::istringstream in(text);
  std::size_t line_no = 0;
  for (std::string raw; std::getline(in, raw);) VOLCOMP_TRY(reader.Line(raw, ++line_no));
  return reader.Finish();
}

std::string FormatEtalonExchange(const Iso230Set& set, const std::vector<std::string>& header) {
  using iso230_text::Fixed;
  std::string out = iso230_text::CommentLines(header);
  for (const Iso230Parameter& p : set.parameters) {
    out += "[" + p.name + "]\n";
    if (!p.tabulated) {
      out += "VALUE = " + Fixed(p.values.front(), iso230_text::kValueDecimals) + "\n";
      continue;
    }
    out += "Gridpoints = {\n";
    for (std::size_t i = 0; i < p.values.size(); ++i) {
      out += "  " + Fixed(p.arguments[i], iso230_text::kArgumentDecimals) + " " +
             Fixed(p.values[i], iso230_text::kValueDecimals) + "\n";
    }
    out += "}\n";
  }
  return out;
}

}  // namespace volcomp::datasets
