#pragma once
// Model tables as std::variant lists (contact laws, drag laws): each alternative names itself with
// a static `name`, the name a config chooses it by. Two alternatives with one name would compile,
// and a config could never choose the second; the registries assert that they do not.
#include <array>
#include <cstddef>
#include <string_view>
#include <utility>
#include <variant>

namespace lbdem {

/// True if no two alternatives of the variant V share their `name`.
template <class V>
constexpr bool variant_names_unique() {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    constexpr std::array<std::string_view, sizeof...(I)> names{
        std::string_view(std::variant_alternative_t<I, V>::name)...};
    for (std::size_t a = 0; a < names.size(); ++a)
      for (std::size_t b = a + 1; b < names.size(); ++b)
        if (names[a] == names[b]) return false;
    return true;
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
}

}  // namespace lbdem
