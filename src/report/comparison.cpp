#include "dynpos/report/comparison.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "dynpos/core/error.hpp"
#include "dynpos/io/text_file.hpp"

namespace dynpos::report {
namespace {

using nlohmann::json;

constexpr const char* kMissing = "—";

bool is_numeric_or_null(const json* j) {
  return j == nullptr || j->is_null() || (j->is_number() && !j->is_boolean());
}

std::optional<double> number_of(const json* j) {
  if (j == nullptr || !j->is_number()) return std::nullopt;
  const double v = j->get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// A short, exact-enough label for a key value: 20 → "20", 12.5 → "12.5".
std::string key_number(double v) { return fmt::format("{:g}", v); }

bool all_objects_with(const json& arr, const char* key) {
  return std::all_of(arr.begin(), arr.end(),
                     [key](const json& e) { return e.is_object() && e.contains(key); });
}

struct Pair {
  const json* a = nullptr;
  const json* b = nullptr;
  std::string label;  // "[name=fwd]", "[t_step=20]", "[1]"
};

// Text key of an item by "name" or by "direction_deg" (each with "case" when present).
std::string text_key(const json& item, const char* key) {
  std::string k;
  const json& v = item.at(key);
  if (v.is_string()) {
    k = v.get<std::string>();
  } else if (v.is_number()) {
    k = key_number(v.get<double>());
  } else {
    k = v.dump();
  }
  if (item.contains("case") && item.at("case").is_string()) {
    return fmt::format("[{}={},{}]", key, k, item.at("case").get<std::string>());
  }
  return fmt::format("[{}={}]", key, k);
}

// Each item of A with the first unpaired item of B of the same key; O(n log n).
std::vector<Pair> pair_by_text_key(const json& a, const json& b, const char* key) {
  std::vector<std::string> b_keys;
  std::map<std::string_view, std::deque<std::size_t>> unpaired;
  for (std::size_t i = 0; i < b.size(); ++i) b_keys.push_back(text_key(b[i], key));
  for (std::size_t i = 0; i < b.size(); ++i) unpaired[b_keys[i]].push_back(i);
  std::vector<Pair> pairs;
  std::vector<bool> used(b.size(), false);
  for (const json& ea : a) {
    Pair p{&ea, nullptr, text_key(ea, key)};
    if (const auto it = unpaired.find(p.label); it != unpaired.end() && !it->second.empty()) {
      p.b = &b[it->second.front()];
      used[it->second.front()] = true;
      it->second.pop_front();
    }
    pairs.push_back(p);
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!used[i]) pairs.push_back({nullptr, &b[i], b_keys[i]});
  }
  return pairs;
}

// Step tests: each item of A with the nearest unpaired item of B within the tolerance; of
// equally near ones the first in B, so that a document compared with itself pairs each item
// with itself, repeated times included. O(n log n): B's unpaired items by time.
std::vector<Pair> pair_by_time(const json& a, const json& b, const char* key, double tol) {
  auto time_of = [key](const json& e) {
    const json& v = e.at(key);
    return v.is_number() ? v.get<double>() : std::nan("");
  };
  std::map<double, std::deque<std::size_t>> unpaired;  // time → indices in B, in order
  std::deque<std::size_t> untimed;  // items of B whose time is not a number, in order
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double t = time_of(b[i]);
    (std::isnan(t) ? untimed : unpaired[t]).push_back(i);
  }
  std::vector<Pair> pairs;
  std::vector<bool> used(b.size(), false);
  for (const json& ea : a) {
    const double ta = time_of(ea);
    Pair p{&ea, nullptr, fmt::format("[{}={}]", key, key_number(ta))};
    auto best = unpaired.end();
    double best_dt = tol;
    const auto consider = [&](auto it) {
      const double dt = std::abs(it->first - ta);
      if (!(dt <= best_dt)) return;
      if (best == unpaired.end() || dt < best_dt || it->second.front() < best->second.front()) {
        best = it;
        best_dt = dt;
      }
    };
    if (std::isnan(ta) && !untimed.empty()) {  // untimed items pair in their order
      p.b = &b[untimed.front()];
      used[untimed.front()] = true;
      untimed.pop_front();
    } else if (!std::isnan(ta)) {
      const auto right = unpaired.lower_bound(ta);
      if (right != unpaired.end()) consider(right);
      if (right != unpaired.begin()) consider(std::prev(right));
    }
    if (best != unpaired.end()) {
      const std::size_t i = best->second.front();
      p.b = &b[i];
      used[i] = true;
      best->second.pop_front();
      if (best->second.empty()) unpaired.erase(best);
    }
    pairs.push_back(p);
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!used[i])
      pairs.push_back({nullptr, &b[i], fmt::format("[{}={}]", key, key_number(time_of(b[i])))});
  }
  return pairs;
}

std::vector<Pair> pair_by_index(const json* a, const json* b) {
  const std::size_t na = a ? a->size() : 0;
  const std::size_t nb = b ? b->size() : 0;
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < std::max(na, nb); ++i) {
    pairs.push_back(
        {i < na ? &(*a)[i] : nullptr, i < nb ? &(*b)[i] : nullptr, fmt::format("[{}]", i + 1)});
  }
  return pairs;
}

std::vector<Pair> pair_items(const json* a, const json* b, const ComparisonOptions& opt) {
  static const json kEmpty = json::array();
  const json& ja = a ? *a : kEmpty;
  const json& jb = b ? *b : kEmpty;
  auto both = [&](const char* key) {
    return all_objects_with(ja, key) && all_objects_with(jb, key);
  };
  const bool objects = !(ja.empty() && jb.empty());
  if (objects && both("name")) return pair_by_text_key(ja, jb, "name");
  if (objects && both("direction_deg")) return pair_by_text_key(ja, jb, "direction_deg");
  if (objects && both("t_step")) return pair_by_time(ja, jb, "t_step", opt.t_step_match_s);
  return pair_by_index(a, b);
}

class Flattener {
 public:
  Flattener(const ComparisonOptions& opt, ComparisonResult& out) : opt_(opt), out_(out) {}

  void node(const json* a, const json* b, const std::string& path, const std::string& key) {
    if (a == nullptr && b == nullptr) return;
    const json* any = (a != nullptr && !a->is_null()) ? a : b;
    if (any == nullptr) any = a;
    if (is_numeric_or_null(a) && is_numeric_or_null(b)) {
      leaf(a, b, path);
    } else if (any->is_string() || (a && a->is_string()) || (b && b->is_string())) {
      text(a, b, path, key);
    } else if (any->is_object() && (a == nullptr || a->is_object() || a->is_null()) &&
               (b == nullptr || b->is_object() || b->is_null())) {
      object(a && a->is_object() ? a : nullptr, b && b->is_object() ? b : nullptr, path);
    } else if (any->is_array() && (a == nullptr || a->is_array() || a->is_null()) &&
               (b == nullptr || b->is_array() || b->is_null())) {
      array(a && a->is_array() ? a : nullptr, b && b->is_array() ? b : nullptr, path);
    }
    // Booleans and mixed types are not figures.
  }

 private:
  void leaf(const json* a, const json* b, const std::string& path) {
    ComparisonRow r;
    r.figure = path;
    r.a = number_of(a);
    r.b = number_of(b);
    if (a == nullptr) ++out_.only_in_b;
    if (b == nullptr) ++out_.only_in_a;
    out_.rows.push_back(std::move(r));
  }

  void text(const json* a, const json* b, const std::string& path, const std::string& key) {
    if (std::find(opt_.text_keys.begin(), opt_.text_keys.end(), key) == opt_.text_keys.end()) {
      return;
    }
    auto str = [](const json* j) {
      if (j == nullptr || j->is_null()) return std::string(kMissing);
      return j->is_string() ? j->get<std::string>() : j->dump();
    };
    ComparisonRow r;
    r.figure = path;
    r.text = true;
    r.a_text = str(a);
    r.b_text = str(b);
    if (r.a_text != r.b_text) out_.rows.push_back(std::move(r));
  }

  void object(const json* a, const json* b, const std::string& path) {
    std::vector<std::string> keys;
    for (const json* j : {a, b}) {
      if (j == nullptr) continue;
      for (auto it = j->begin(); it != j->end(); ++it) {
        if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) keys.push_back(it.key());
      }
    }
    for (const std::string& k : keys) {
      const json* ca = a && a->contains(k) ? &a->at(k) : nullptr;
      const json* cb = b && b->contains(k) ? &b->at(k) : nullptr;
      node(ca, cb, path.empty() ? k : path + "." + k, k);
    }
  }

  void array(const json* a, const json* b, const std::string& path) {
    for (const Pair& p : pair_items(a, b, opt_)) node(p.a, p.b, path + p.label, "");
  }

  const ComparisonOptions& opt_;
  ComparisonResult& out_;
};

std::string number_cell(const std::optional<double>& v) {
  if (!v) return kMissing;
  const double x = *v;
  const double ax = std::abs(x);
  if (ax != 0.0 && (ax >= 1e7 || ax < 1e-3)) return fmt::format("{:.4g}", x);
  if (ax >= 1e4) return fmt::format("{:.0f}", x);
  return fmt::format("{:.4g}", x);
}

json opt_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

}  // namespace

std::string result_kind(const json& doc) {
  if (!doc.is_object()) return "generic";
  if (doc.contains("analysis") && doc.at("analysis").is_string()) {
    return doc.at("analysis").get<std::string>();
  }
  if (doc.contains("steps") && doc.at("steps").is_array()) return "step";
  if (doc.contains("legs") && doc.at("legs").is_array()) return "four-corner";
  if (doc.contains("directions") && doc.at("directions").is_array()) return "agility";
  if (doc.contains("arms") && doc.at("arms").is_array()) return "leverarm";
  if (doc.contains("position_std_m") || doc.contains("windows")) return "station-keeping";
  if (doc.contains("case") && doc.at("case").is_string() &&
      (doc.contains("variant") || doc.contains("conventional"))) {
    return "hybrid " + doc.at("case").get<std::string>();
  }
  return "generic";
}

std::optional<double> ComparisonRow::difference() const {
  if (!a || !b) return std::nullopt;
  return *b - *a;
}

std::optional<double> ComparisonRow::relative_difference_pct() const {
  if (!a || !b || *a == 0.0) return std::nullopt;
  return 100.0 * (*b - *a) / std::abs(*a);
}

ComparisonResult compare_results(const json& a, const json& b, const ComparisonOptions& options) {
  ComparisonResult out;
  const std::string ka = result_kind(a);
  const std::string kb = result_kind(b);
  if (ka != kb) {
    throw std::invalid_argument("A is a '" + ka + "' result but B is a '" + kb + "' result");
  }
  out.kind = ka;
  Flattener(options, out).node(&a, &b, "", "");
  return out;
}

std::pair<std::size_t, std::size_t> line_column_of(const std::string& text, std::size_t byte) {
  // nlohmann counts the characters read, so the offending one is at 0-based index byte - 1.
  const std::size_t at = std::min(byte == 0 ? 0 : byte - 1, text.size());
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return {line, at - line_start + 1};
}

// The deepest nesting a result may have: dynpos' documents are at most 6 deep; the limit
// keeps the flattener's recursion (and the parser's) bounded on hostile input.
constexpr std::size_t kMaxJsonDepth = 64;

// Throws InputError at the first bracket that nests deeper than kMaxJsonDepth.
void check_json_depth(const std::string& text, const std::filesystem::path& path) {
  std::size_t depth = 0;
  bool in_string = false;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        const auto [line, column] = line_column_of(text, i + 1);
        throw core::InputError(
            {path.string(), line, column, {}},
            "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels",
            "give a result written by a dynpos analysis with --json");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

json load_json_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw core::InputError({path.string(), {}, {}, {}}, "cannot open the file",
                           "check the path; give two JSON results written with --json");
  }
  const std::string text =
      io::read_capped(in, path, io::kMaxJsonBytes,
                      "give a result written by a dynpos analysis with --json (a few MB at most)");
  check_json_depth(text, path);
  try {
    return json::parse(text);
  } catch (const json::out_of_range& e) {
    // A number beyond double's range (e.g. 1e400): nlohmann names the token, not the place.
    std::string what = e.what();
    std::optional<std::size_t> line, column;
    if (const auto q = what.find('\''); q != std::string::npos) {
      const auto q2 = what.find('\'', q + 1);
      const std::string token = what.substr(q + 1, q2 - q - 1);
      if (const auto at = text.find(token); !token.empty() && at != std::string::npos) {
        std::tie(line, column) = line_column_of(text, at + 1);
      }
    }
    if (const auto p = what.find("number overflow"); p != std::string::npos) what = what.substr(p);
    throw core::InputError({path.string(), line, column, {}}, "invalid JSON: " + what,
                           "numbers must be finite doubles (about ±1.8e308)");
  } catch (const json::parse_error& e) {
    const auto [line, column] = line_column_of(text, e.byte);
    std::string what = e.what();
    // Keep nlohmann's description without its own position prefix.
    if (const auto p = what.find("syntax error"); p != std::string::npos) what = what.substr(p);
    throw core::InputError({path.string(), line, column, {}}, "invalid JSON: " + what,
                           "give a result written by a dynpos analysis with --json");
  }
}

Table comparison_table(const ComparisonResult& result, const std::string& label_a,
                       const std::string& label_b) {
  Table t;
  t.header = {"figure", label_a, label_b, "B − A", "(B − A)/|A| [%]"};
  for (const ComparisonRow& r : result.rows) {
    if (r.text) {
      t.rows.push_back({r.figure, r.a_text, r.b_text, kMissing, kMissing});
      continue;
    }
    const auto rel = r.relative_difference_pct();
    t.rows.push_back({r.figure, number_cell(r.a), number_cell(r.b), number_cell(r.difference()),
                      rel ? fmt::format("{:+.1f}", *rel) : std::string(kMissing)});
  }
  return t;
}

json comparison_json(const ComparisonResult& result, const std::string& label_a,
                     const std::string& label_b) {
  json doc;
  doc["analysis"] = "compare";
  doc["kind"] = result.kind;
  doc["labels"] = {label_a, label_b};
  doc["only_in_a"] = result.only_in_a;
  doc["only_in_b"] = result.only_in_b;
  doc["rows"] = json::array();
  for (const ComparisonRow& r : result.rows) {
    json j;
    j["figure"] = r.figure;
    if (r.text) {
      j["a"] = r.a_text;
      j["b"] = r.b_text;
    } else {
      j["a"] = opt_json(r.a);
      j["b"] = opt_json(r.b);
      j["difference"] = opt_json(r.difference());
      j["relative_difference_pct"] = opt_json(r.relative_difference_pct());
    }
    doc["rows"].push_back(j);
  }
  return doc;
}

}  // namespace dynpos::report
