#include "param_fields.hpp"

#include <set>

namespace dynpos::scenario::detail {

void read_fields(const TomlTable& t, const std::vector<core::ParamField>& fields,
                 const std::vector<std::string>& other_keys) {
  std::set<std::string, std::less<>> known(other_keys.begin(), other_keys.end());
  for (const core::ParamField& f : fields) known.insert(f.range.key);
  t.reject_unknown(known);
  for (const core::ParamField& f : fields) {
    if (t.has(f.range.key)) *f.value = t.number(f.range) * f.range.to_si;
  }
}

nlohmann::json fields_to_json(const std::vector<core::ParamField>& fields) {
  nlohmann::json out = nlohmann::json::object();
  for (const core::ParamField& f : fields) out[f.range.key] = *f.value / f.range.to_si;
  return out;
}

}  // namespace dynpos::scenario::detail
