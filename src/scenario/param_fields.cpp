#include "param_fields.hpp"

#include <set>

namespace dynpos::scenario::detail {

void read_fields(const TomlTable& t, const std::vector<ParamField>& fields,
                 const std::vector<std::string>& other_keys) {
  std::set<std::string, std::less<>> known(other_keys.begin(), other_keys.end());
  for (const ParamField& f : fields) known.insert(f.key);
  t.reject_unknown(known);
  for (const ParamField& f : fields) {
    if (t.has(f.key)) *f.value = t.number(f.key, f.lo, f.hi) * f.to_si;
  }
}

nlohmann::json fields_to_json(const std::vector<ParamField>& fields) {
  nlohmann::json out = nlohmann::json::object();
  for (const ParamField& f : fields) out[f.key] = *f.value / f.to_si;
  return out;
}

}  // namespace dynpos::scenario::detail
