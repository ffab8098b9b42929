// Names made unique by a number, as a model's materials, objects and cameras are named in a scene:
// a name itself, else "NAME 2", "NAME 3", ...
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>

namespace engine {

// Each name remembers the next number to try, so that n equal names take n tries, not n²/2
// (a model may give 40,000 materials one name): a taken candidate "NAME k" is tried at most
// once as a number of NAME and once as a name of its own.
class UniqueNames {
 public:
  // The name, or the first of "NAME 2", "NAME 3", ... not given before.
  std::string add(const std::string& name) {
    int& next = next_.try_emplace(name, 1).first->second;
    std::string candidate = next == 1 ? name : numbered(name, next);
    for (++tries_; !taken_.insert(candidate).second; ++tries_) candidate = numbered(name, ++next);
    ++next;
    return candidate;
  }

  // Candidates tried so far (the work done).
  size_t tries() const { return tries_; }

 private:
  static std::string numbered(const std::string& name, int n) { return name + " " + std::to_string(n); }

  std::set<std::string> taken_;
  std::map<std::string, int> next_;  // by name: the next number to try (1: the name itself)
  size_t tries_ = 0;
};

}  // namespace engine
