// read_number.h: a bench's numeric option, read strictly.
// In: the option's name (for the message), its text and, optionally, the closed range it accepts. Out: true and the
// value when the whole text is a number (an integer for an integral type) within the range; otherwise false, the
// value untouched and "NAME takes an integer from MIN to MAX, not 'TEXT'" on stderr. atoi and atof read "abc" as 0
// and "5x" as 5, and the benches then clamped --runs 0 to 1 without a word. Cost: O(length of the text).
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>

template <class T>
bool read_number(const char* name, const char* text, T min, T max, T& value)
{
  static_assert(std::is_arithmetic_v<T> && !(std::is_unsigned_v<T> && sizeof(T) >= sizeof(long long)),
                "read_number reads numbers that a long long or a double holds");
  constexpr bool kIntegral = std::is_integral_v<T>;
  char* end = nullptr;
  errno = 0;
  const long long whole = kIntegral ? std::strtoll(text, &end, 10) : 0;
  const double real = kIntegral ? double(whole) : std::strtod(text, &end);
  const bool ok = errno == 0 && end != text && *end == '\0' && std::isfinite(real) &&
                  (kIntegral ? whole >= static_cast<long long>(min) && whole <= static_cast<long long>(max)
                             : real >= double(min) && real <= double(max));
  if (ok) {
    value = kIntegral ? static_cast<T>(whole) : static_cast<T>(real);
    return true;
  }
  const bool whole_type = min == std::numeric_limits<T>::lowest() && max == std::numeric_limits<T>::max();
  if (whole_type)
    std::fprintf(stderr, "%s takes %s, not '%s'\n", name, kIntegral ? "an integer" : "a number", text);
  else if (kIntegral)
    std::fprintf(stderr, "%s takes an integer from %lld to %lld, not '%s'\n", name, static_cast<long long>(min),
                 static_cast<long long>(max), text);
  else
    std::fprintf(stderr, "%s takes a number from %g to %g, not '%s'\n", name, double(min), double(max), text);
  return false;
}

// Any value of T: the caller checks the range itself.
template <class T>
bool read_number(const char* name, const char* text, T& value)
{
  return read_number(name, text, std::numeric_limits<T>::lowest(), std::numeric_limits<T>::max(), value);
}

// A 0/1 switch.
inline bool read_switch(const char* name, const char* text, bool& value)
{
  int number = 0;
  if (!read_number(name, text, 0, 1, number))
    return false;
  value = number != 0;
  return true;
}

// The benches' limits on repetitions and threads: beyond them a typo, not a measurement.
constexpr int kMaxRuns = 1000, kMaxThreads = 256;
