#include "app/cli/number_option.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace app {

namespace {

std::string rangeText(const NumberLimits& limits) {
  std::ostringstream text;
  text << (limits.aboveMin ? "(" : "[") << limits.min << ", " << limits.max << "]";
  return text.str();
}

// Reads all of `text` as a T into `value`: whether it was read, or why not (invalid_argument,
// result_out_of_range: beyond what a T holds).
template <typename T>
std::errc readAll(const std::string& text, double& value) {
  T read{};
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), read);
  value = static_cast<double>(read);
  return error == std::errc() && stop != text.data() + text.size() ? std::errc::invalid_argument : error;
}

// Why `text` is not a number within `limits`, or nothing when it is one.
std::string refusal(const std::string& text, const NumberLimits& limits, bool whole) {
  double value = 0;
  const std::errc error = whole ? readAll<long long>(text, value) : readAll<double>(text, value);
  const std::string outOfRange = "value out of range: " + text + ", expected " + rangeText(limits);
  if (error == std::errc::result_out_of_range) return outOfRange;
  if (error != std::errc()) return (whole ? "not a whole number: " : "not a number: ") + text;
  if (!std::isfinite(value)) return "not a finite number: " + text;
  if (value < limits.min || (limits.aboveMin && value == limits.min) || value > limits.max) return outOfRange;
  return {};
}

}  // namespace

CLI::Validator numberCheck(const NumberLimits& limits, bool whole) {
  return CLI::Validator([limits, whole](std::string& text) { return refusal(text, limits, whole); }, rangeText(limits),
                        "number");
}

}  // namespace app
