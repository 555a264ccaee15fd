// SpatialAnalyzer point exports, ASCII and XML (see sa_points.hpp for the syntax and sources).
#include "volcomp/datasets/sa_points.hpp"

#include <cctype>
#include <map>
#include <utility>

#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {
namespace {

Failure At(const std::string& source, std::size_t line, const std::string& message) {
  return Failure{Error::kInputInvalid, source + ":" + std::to_string(line) + ": " + message};
}

std::size_t AfterBom(const std::string& text) {
  return text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
}

// The fields of one line: runs of characters other than space, tab, comma and CR.
std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  for (const char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
      if (!field.empty()) out.push_back(std::move(field));
      field.clear();
    } else {
      field += c;
    }
  }
  if (!field.empty()) out.push_back(std::move(field));
  return out;
}

bool IsNumber(const std::string& field) { return tools::ParseDouble(field).has_value(); }

bool IsComment(const std::vector<std::string>& fields) {
  return !fields.empty() && fields[0].compare(0, 2, "//") == 0;
}

// Remembers each name's line; a failure naming both lines when a name comes again.
class NameRegister {
 public:
  explicit NameRegister(const std::string& source) : source_(source) {}
  Outcome Add(const std::string& name, std::size_t line) {
    const auto first = lines_.emplace(name, line);
    if (first.second) return Outcome::Ok();
    return Fail(At(source_, line,
                   "point \"" + name + "\" given twice (first on line " +
                       std::to_string(first.first->second) +
                       "); every point needs its own name to be paired"));
  }

 private:
  const std::string& source_;
  std::map<std::string, std::size_t> lines_;
};

// ---- XML ----

std::string Upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string Decoded(const std::string& s) {
  static const std::pair<const char*, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool matched = false;
    for (const auto& e : kEntities) {
      const std::string name = e.first;
      if (s.compare(i, name.size(), name) == 0) {
        out += e.second;
        i += name.size();
        matched = true;
        break;
      }
    }
    if (!matched) out += s[i++];
  }
  return out;
}

// One tag: its upper-case name, whether it closes (</X>) or is empty (<X/>), its attributes
// (upper-case names, decoded values).
struct Tag {
  std::string name;
  bool closing = false;
  bool empty = false;
  std::map<std::string, std::string> attributes;
};

// Parses the inside of `<...>`; false when the attribute syntax is broken.
bool ParseTag(std::string body, Tag& tag) {
  if (!body.empty() && body.back() == '/') {
    tag.empty = true;
    body.pop_back();
  }
  std::size_t i = 0;
  if (i < body.size() && body[i] == '/') {
    tag.closing = true;
    ++i;
  }
  const auto space = [&](std::size_t k) {
    return k < body.size() && std::isspace(static_cast<unsigned char>(body[k]));
  };
  const std::size_t name_start = i;
  while (i < body.size() && !space(i)) ++i;
  tag.name = Upper(body.substr(name_start, i - name_start));
  while (true) {
    while (space(i)) ++i;
    if (i >= body.size()) return !tag.name.empty();
    const std::size_t key_start = i;
    while (i < body.size() && body[i] != '=' && !space(i)) ++i;
    const std::string key = Upper(body.substr(key_start, i - key_start));
    while (space(i)) ++i;
    if (i >= body.size() || body[i] != '=') return false;
    ++i;
    while (space(i)) ++i;
    if (i >= body.size() || (body[i] != '"' && body[i] != '\'')) return false;
    const char quote = body[i++];
    const std::size_t end = body.find(quote, i);
    if (end == std::string::npos) return false;
    tag.attributes[key] = Decoded(body.substr(i, end - i));
    i = end + 1;
  }
}

Expected<model::Vec3> XyzOf(const Tag& tag,
                            const std::string& source,
                            std::size_t line,
                            const std::string& point,
                            double mm_per_unit) {
  model::Vec3 v;
  for (int a = 0; a < 3; ++a) {
    const std::string key(1, "XYZ"[a]);
    const auto it = tag.attributes.find(key);
    const auto value = it == tag.attributes.end() ? std::nullopt : tools::ParseDouble(it->second);
    if (!value) {
      return Fail(At(source, line,
                     "point \"" + point + "\": " + tag.name + " " + key +
                         (it == tag.attributes.end() ? " is missing"
                                                     : " \"" + it->second + "\" is not a number")));
    }
    v[a] = *value * mm_per_unit;
  }
  return v;
}

}  // namespace

double MillimetresPer(SaUnit unit) {
  switch (unit) {
    case SaUnit::kInch:
      return 25.4;
    case SaUnit::kMetre:
      return 1000.0;
    case SaUnit::kMillimetre:
      break;
  }
  return 1.0;
}

Expected<std::vector<SaPoint>> SaPointsFromAscii(const std::string& text,
                                                 const std::string& source,
                                                 SaUnit unit,
                                                 std::optional<int> name_fields) {
  if (name_fields && (*name_fields < 0 || *name_fields > 3)) {
    return Fail(Error::kInvalidArgument,
                "the name has 0 to 3 parts, not " + std::to_string(*name_fields));
  }
  std::vector<SaPoint> points;
  NameRegister names(source);
  std::size_t line = 0;
  for (std::size_t begin = AfterBom(text); begin < text.size();) {
    ++line;
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string raw = text.substr(begin, end - begin);
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::vector<std::string> f = Fields(raw);
    begin = end + 1;
    if (f.empty() || IsComment(f)) continue;
    std::size_t n = 0;
    if (name_fields) {
      n = static_cast<std::size_t>(*name_fields);
    } else {
      while (n < f.size() && !IsNumber(f[n])) ++n;
    }
    if (f.size() < n + 3 || !IsNumber(f[n]) || !IsNumber(f[n + 1]) || !IsNumber(f[n + 2])) {
      return Fail(At(source, line,
                     "expected [name parts] x y z [extra...], got \"" + raw + "\"" +
                         (name_fields ? " (with " + std::to_string(n) + " name parts)" : "")));
    }
    if (n == 0) {
      return Fail(At(source, line,
                     "point without a name: volcomp pairs points by name (export with the "
                     "Target name, or give the count of name parts)"));
    }
    if (n > 3) {
      return Fail(At(source, line,
                     "\"" + f[3] + "\": a name has at most 3 parts (Collection Group Target)"));
    }
    SaPoint p;
    for (std::size_t k = 0; k < n; ++k) p.name += (k ? " " : "") + f[k];
    for (int a = 0; a < 3; ++a) {
      p.position_mm[a] =
          *tools::ParseDouble(f[n + static_cast<std::size_t>(a)]) * MillimetresPer(unit);
    }
    p.line = line;
    VOLCOMP_TRY(names.Add(p.name, line));
    points.push_back(std::move(p));
  }
  if (points.empty()) return Fail(Error::kInputInvalid, source + ": no points");
  return points;
}

Expected<std::vector<SaPointPair>> SaPairsFromXml(const std::string& text,
                                                  const std::string& source,
                                                  SaUnit unit) {
  std::vector<SaPointPair> pairs;
  NameRegister names(source);
  std::optional<SaPointPair> open;  // the POINT being read
  bool has_nominal = false, has_actual = false;
  std::size_t line = 1;
  const auto count_lines = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < text.size(); ++k) line += text[k] == '\n';
  };
  std::size_t i = AfterBom(text);
  while (true) {
    const std::size_t lt = text.find('<', i);
    count_lines(i, lt);
    if (lt == std::string::npos) break;
    const bool comment = text.compare(lt, 4, "<!--") == 0;
    const std::size_t gt = comment ? text.find("-->", lt) : text.find('>', lt);
    if (gt == std::string::npos) return Fail(At(source, line, "a tag is not closed"));
    const std::size_t tag_line = line;
    count_lines(lt, gt);
    i = gt + (comment ? 3 : 1);
    if (comment || text[lt + 1] == '?' || text[lt + 1] == '!') continue;
    Tag tag;
    if (!ParseTag(text.substr(lt + 1, gt - lt - 1), tag)) {
      return Fail(At(source, tag_line, "cannot read the tag's attributes"));
    }
    if (tag.name == "POINT" && !tag.closing) {
      if (open) {
        return Fail(At(source, tag_line,
                       "a POINT inside point \"" + open->name + "\" (line " +
                           std::to_string(open->line) + ")"));
      }
      const auto name = tag.attributes.find("NAME");
      if (name == tag.attributes.end() || name->second.empty()) {
        return Fail(At(source, tag_line, "a POINT without a NAME"));
      }
      open = SaPointPair{name->second, {}, {}, tag_line};
      has_nominal = has_actual = false;
      VOLCOMP_TRY(names.Add(open->name, tag_line));
    } else if ((tag.name == "NOMINAL" || tag.name == "ACTUAL") && !tag.closing) {
      const bool nominal = tag.name == "NOMINAL";
      if (!open)
        return Fail(At(source, tag_line,
                       (nominal ? "a NOMINAL" : "an ACTUAL") + std::string(" outside a POINT")));
      if (nominal ? has_nominal : has_actual) {
        return Fail(At(source, tag_line,
                       "point \"" + open->name + "\" has a second " + tag.name +
                           " (one nominal/actual pair per POINT)"));
      }
      VOLCOMP_TRY_ASSIGN((nominal ? open->nominal_mm : open->actual_mm),
                         XyzOf(tag, source, tag_line, open->name, MillimetresPer(unit)));
      (nominal ? has_nominal : has_actual) = true;
    }
    if (tag.name == "POINT" && open && (tag.closing || tag.empty)) {
      if (!has_nominal || !has_actual) {
        return Fail(At(source, open->line,
                       "point \"" + open->name + "\" has no " +
                           (has_nominal ? "ACTUAL" : "NOMINAL") +
                           " (each POINT needs a NOMINAL and an ACTUAL X Y Z)"));
      }
      pairs.push_back(std::move(*open));
      open.reset();
    }
  }
  if (open) return Fail(At(source, open->line, "point \"" + open->name + "\" is not closed"));
  if (pairs.empty()) return Fail(Error::kInputInvalid, source + ": no POINT elements");
  return pairs;
}

bool LooksLikeSaXml(const std::string& text) {
  for (std::size_t i = AfterBom(text); i < text.size(); ++i) {
    if (!std::isspace(static_cast<unsigned char>(text[i]))) return text[i] == '<';
  }
  return false;
}

bool LooksLikeSaAscii(const std::string& text) {
  for (std::size_t begin = AfterBom(text); begin < text.size();) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    const std::vector<std::string> f = Fields(text.substr(begin, end - begin));
    begin = end + 1;
    if (f.empty()) continue;
    if (IsComment(f)) return true;
    for (std::size_t k = 0; k + 2 < f.size(); ++k) {
      if (IsNumber(f[k]) && IsNumber(f[k + 1]) && IsNumber(f[k + 2])) return true;
    }
    return false;
  }
  return false;
}

}  // namespace volcomp::datasets
