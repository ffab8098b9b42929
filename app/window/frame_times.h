// The times between the window's frames, for `walkrad view --stats`.
#pragma once

#include <cstddef>
#include <vector>

namespace app {

class FrameTimes {
 public:
  void add(double milliseconds) { times_.push_back(milliseconds); }
  size_t count() const { return times_.size(); }
  // The q-quantile (0 <= q <= 1) by the nearest rank: the smallest time at least a share q of
  // the frames took at most; 0 with no frames.
  double quantile(double q) const;

 private:
  std::vector<double> times_;
};

}  // namespace app
