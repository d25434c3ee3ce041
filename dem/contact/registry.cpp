#include "dem/contact/registry.hpp"

#include <algorithm>

#include "core/config.hpp"
#include "core/error.hpp"

namespace lbdem::dem {

namespace {
template <class V>
V pick(const std::string& name, const std::vector<std::string>& names, const char* key) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InputError(key, "\"" + name + "\"", "unknown model; known: " + list,
                     "did you mean \"" + nearest(name, names) + "\"?");
  }
  V v;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((I == static_cast<std::size_t>(it - names.begin()) ? (v.template emplace<I>(), 0) : 0), ...);
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
  return v;
}
}  // namespace

NormalVariant normal_law(const std::string& name) {
  return pick<NormalVariant>(name, kNormalLaws, "contact.normal");
}

AnyLawTable make_law_table(const ContactSettings& s, const std::vector<Material>& materials) {
  const auto nv = normal_law(s.normal);
  const auto rv = pick<RollingVariant>(s.rolling, kRollingModels, "contact.rolling");
  const auto cv = pick<CohesionVariant>(s.cohesion, kCohesionModels, "contact.cohesion");
  return std::visit(
      [&](auto n, auto r, auto c) -> AnyLawTable {
        using Law = ContactLaw<decltype(n), decltype(r), decltype(c)>;
        LawTable<Law> t;
        const int nm = static_cast<int>(materials.size());
        t.n_materials = nm;
        for (int a = 0; a < nm; ++a)
          for (int b = 0; b < nm; ++b) {
            t.pp.push_back(law_params<Law>(mix(materials[a], materials[b]), s));
            t.range = std::max(t.range, Law::range(t.pp.back()));
          }
        // Walls: a particle of material a against a wall of material w (any material in the list).
        t.pw = t.pp;
        return t;
      },
      nv, rv, cv);
}

}  // namespace lbdem::dem
