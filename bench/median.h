// median.h: the figure every bench prints, the median of repeated measurements.
// In: the measurements (taken by value: sorted here). Out: the middle one, the mean of the two middle ones for an
// even count, NaN for none (printed as "nan", never mistaken for a time). Cost: O(n log n).
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

inline double median(std::vector<double> v)
{
  if (v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}
