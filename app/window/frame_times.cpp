#include "app/window/frame_times.h"

#include <algorithm>
#include <cmath>

namespace app {

double FrameTimes::quantile(double q) const {
  if (times_.empty()) return 0;
  std::vector<double> sorted = times_;
  const auto rank = static_cast<size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  const size_t index = std::clamp<size_t>(rank, 1, sorted.size()) - 1;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(index), sorted.end());
  return sorted[index];
}

}  // namespace app
