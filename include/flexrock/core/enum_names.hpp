// SPDX-License-Identifier: BSD-3-Clause
// Enumerations named by tables: one row {value, name} per enumerator, read both ways (the name of a
// value for writers and messages, the value of a name for readers), so that a new enumerator is
// one row and no switch or list of enumerators elsewhere can miss it.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace flexrock {

/// One row of a table of names: an enumerator and its stable text.
template <class E>
struct EnumName {
  E value;
  const char* name;
};

/// The name of `value` in `table`, or `unknown` for a value the table lacks.
template <class E, std::size_t N>
constexpr const char* name_of(const EnumName<E> (&table)[N], E value,
                              const char* unknown = "unknown") {
  for (const EnumName<E>& row : table) {
    if (row.value == value) return row.name;
  }
  return unknown;
}

/// The value named `name` in `table`, or nullopt.
template <class E, std::size_t N>
constexpr std::optional<E> value_named(const EnumName<E> (&table)[N], std::string_view name) {
  for (const EnumName<E>& row : table) {
    if (name == row.name) return row.value;
  }
  return std::nullopt;
}

}  // namespace flexrock
