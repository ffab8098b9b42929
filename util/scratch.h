// Scratch split into many pieces that a long run fills again call after call (the solver's
// receiver chunks, the emulated Pixel-Planes 5's batches): each piece's vectors keep the capacity
// of the largest call that filled them, and different calls fill different pieces, so together
// they come to hold the sum of every piece's largest, many times what any one call needs (on a
// building, 800 MB after a shot that needed 535 MB and others that needed 40). These let the
// owner give back what the last call left spare.
#pragma once

#include <cstddef>
#include <type_traits>
#include <vector>

namespace util {

// The bytes `vectors` hold (their capacities).
template <class... T>
size_t heldBytes(const std::vector<T>&... vectors) {
  return (size_t{0} + ... + (vectors.capacity() * sizeof(T)));
}

// Frees each of `vectors`, whose contents are no longer needed, that holds more than twice what
// the last call filled.
template <class... T>
void releaseSpare(std::vector<T>&... vectors) {
  const auto release = [](auto& v) {
    if (v.capacity() > 2 * v.size()) std::decay_t<decltype(v)>().swap(v);
  };
  (release(vectors), ...);
}

// When `pieces` (each with heldBytes() and releaseSpare(), as above) hold more than `bound` bytes
// in all, each releases what it holds spare. Returns the bytes they hold then. Below the bound
// nothing changes, so a small scene's run keeps its scratch as before.
template <class Pieces>
size_t releaseSpareBeyond(Pieces& pieces, size_t bound) {
  const auto held = [&] {
    size_t bytes = 0;
    for (const auto& piece : pieces) bytes += piece.heldBytes();
    return bytes;
  };
  if (const size_t before = held(); before <= bound) return before;
  for (auto& piece : pieces) piece.releaseSpare();
  return held();
}

}  // namespace util
