// Checks of invariants (after pbrt-v4's check.h): a failure is a bug in walkrad, not bad input,
// so it says where and what and aborts instead of going on with a broken state. Bad input gets
// a located error instead (engine/diagnostics.h).
//
//   CHECK(condition)                 always on
//   CHECK_EQ/NE/LT/LE/GT/GE(a, b)    always on; each argument evaluated once
//   DCHECK, DCHECK_EQ/NE/LT/LE/GT/GE for checks too costly to ship: on when
//                                    WALKRAD_DCHECK_IS_ON (debug and sanitizer builds); in
//                                    release builds compiled but never run, so their arguments
//                                    are not evaluated and cannot rot
//
// A failure prints one line to stderr and aborts:
//   mesher/adaptive_mesh.cpp:221: CHECK failed: tVertices() == 0u (tVertices() = 2, 0u = 0)
#pragma once

#include <concepts>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>

// A translation unit may decide for itself by defining it first (the tests do, to check both).
#ifndef WALKRAD_DCHECK_IS_ON
#if defined(__has_feature)  // clang
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define WALKRAD_DCHECK_SANITIZED_ 1
#endif
#endif
#if !defined(NDEBUG) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || defined(WALKRAD_DCHECK_SANITIZED_)
#define WALKRAD_DCHECK_IS_ON 1
#else
#define WALKRAD_DCHECK_IS_ON 0
#endif
#endif

namespace util::check_detail {

[[noreturn]] inline void fail(const char* file, int line, const char* expression, const std::string& values) {
  std::fprintf(stderr, "%s:%d: CHECK failed: %s%s\n", file, line, expression, values.c_str());
  std::fflush(stderr);
  std::abort();
}

// Numbers in full (a failed == on doubles shows where they differ), small integers as numbers
// rather than characters.
template <typename T>
void printValue(std::ostream& out, const T& value) {
  if constexpr (std::is_same_v<T, bool>) {
    out << (value ? "true" : "false");
  } else if constexpr (std::is_integral_v<T> && sizeof(T) == 1) {
    out << static_cast<int>(value);
  } else if constexpr (std::is_floating_point_v<T>) {
    out.precision(std::numeric_limits<T>::max_digits10);
    out << value;
  } else if constexpr (requires { out << value; }) {
    out << value;
  } else {
    out << "(not printable)";
  }
}

template <typename A, typename B>
[[noreturn]] void failComparison(const char* file, int line, const char* expression, const char* aText, const A& a,
                                 const char* bText, const B& b) {
  std::ostringstream values;
  values << " (" << aText << " = ";
  printValue(values, a);
  values << ", " << bText << " = ";
  printValue(values, b);
  values << ")";
  fail(file, line, expression, values.str());
}

}  // namespace util::check_detail

#define CHECK(condition)                                                                 \
  do {                                                                                   \
    if (!(condition)) [[unlikely]]                                                       \
      ::util::check_detail::fail(__FILE__, __LINE__, #condition, std::string());         \
  } while (false)

#define WALKRAD_CHECK_OP_(a, b, op)                                                                    \
  do {                                                                                                 \
    const auto& walkradCheckA_ = (a);                                                                  \
    const auto& walkradCheckB_ = (b);                                                                  \
    if (!(walkradCheckA_ op walkradCheckB_)) [[unlikely]]                                              \
      ::util::check_detail::failComparison(__FILE__, __LINE__, #a " " #op " " #b, #a, walkradCheckA_, \
                                           #b, walkradCheckB_);                                        \
  } while (false)

#define CHECK_EQ(a, b) WALKRAD_CHECK_OP_(a, b, ==)
#define CHECK_NE(a, b) WALKRAD_CHECK_OP_(a, b, !=)
#define CHECK_LT(a, b) WALKRAD_CHECK_OP_(a, b, <)
#define CHECK_LE(a, b) WALKRAD_CHECK_OP_(a, b, <=)
#define CHECK_GT(a, b) WALKRAD_CHECK_OP_(a, b, >)
#define CHECK_GE(a, b) WALKRAD_CHECK_OP_(a, b, >=)

// The mode is read where a DCHECK is used, so one header serves both.
#define WALKRAD_DCHECK_(check)                 \
  do {                                         \
    if constexpr (WALKRAD_DCHECK_IS_ON) check; \
  } while (false)

#define DCHECK(condition) WALKRAD_DCHECK_(CHECK(condition))
#define DCHECK_EQ(a, b) WALKRAD_DCHECK_(CHECK_EQ(a, b))
#define DCHECK_NE(a, b) WALKRAD_DCHECK_(CHECK_NE(a, b))
#define DCHECK_LT(a, b) WALKRAD_DCHECK_(CHECK_LT(a, b))
#define DCHECK_LE(a, b) WALKRAD_DCHECK_(CHECK_LE(a, b))
#define DCHECK_GT(a, b) WALKRAD_DCHECK_(CHECK_GT(a, b))
#define DCHECK_GE(a, b) WALKRAD_DCHECK_(CHECK_GE(a, b))
