// What every registry of flowform does with its one list of types (friction laws, material
// laws, responses): a compile-time list a new entry is added to, a dispatch from a run-time
// index to the entry's static functions, and the lookup of an entry's index by its name.
#pragma once

#include <string>
#include <vector>

namespace flowform {

template <typename... Types>
struct TypeList {};

/// Stands for type T in a generic lambda: `[&](auto tag) { using T = typename decltype(tag)::type; }`.
template <typename T>
struct TypeTag {
  using type = T;
};

/// Calls f(TypeTag<T>{}) for the index-th type T of the list; false (f not called) when there
/// is none. The fold stops at the match, so a dispatch costs index + 1 comparisons.
template <typename... Types, typename F>
bool visitByIndex(TypeList<Types...>, int index, F&& f) {
  int i = 0;
  return ((i++ == index ? (f(TypeTag<Types>{}), true) : false) || ...);
}

/// Index of the entry called `name` in a registry's list of facts (each has a `name`), −1 when
/// there is none.
template <typename Info>
int indexByName(const std::vector<Info>& list, const std::string& name) {
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].name == name) return static_cast<int>(i);
  return -1;
}

/// The entries' names for a message: 'A', 'B', 'C'.
template <typename Info>
std::string quotedNames(const std::vector<Info>& list) {
  std::string names;
  for (const Info& entry : list) names += (names.empty() ? "'" : ", '") + std::string(entry.name) + "'";
  return names;
}

}  // namespace flowform
