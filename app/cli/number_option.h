// The command line's numbers. Every numeric option of every subcommand is added through
// addNumberOption, whose check refuses what is not a finite number within the option's limits
// (CLI11's own validators let NaN through: every comparison with it is false), so no NaN,
// infinity, negative count or overflowing integer reaches a loop bound or a cast.
// tests/cli/cli_tests.cmake finds every numeric option in `--help` and tries each.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <type_traits>

namespace app {

// [min, max], or (min, max] when `aboveMin` (a size or a fraction that must not be 0).
struct NumberLimits {
  double min = 0, max = 0;
  bool aboveMin = false;
};
constexpr NumberLimits inRange(double min, double max) { return {min, max, false}; }
constexpr NumberLimits positiveUpTo(double max) { return {0, max, true}; }

// A CLI11 check that the text is a number within `limits` (a whole number, in decimal, when
// `whole`): finite, not beyond what a double or a 64-bit integer holds. Its message ("not a
// finite number: nan", "value out of range: 2, expected (0, 1]") follows the option's name.
CLI::Validator numberCheck(const NumberLimits& limits, bool whole);

namespace detail {
template <typename T> struct NumberOf { using type = T; };
template <typename T> struct NumberOf<std::optional<T>> { using type = T; };
}  // namespace detail

// Adds `name` to `command`, read into `value` (a number, or an optional one) once checked.
template <typename T>
CLI::Option* addNumberOption(CLI::App& command, const std::string& name, T& value, const NumberLimits& limits,
                             const std::string& help) {
  constexpr bool whole = std::is_integral_v<typename detail::NumberOf<T>::type>;
  return command.add_option(name, value, help)->check(numberCheck(limits, whole));
}

}  // namespace app
