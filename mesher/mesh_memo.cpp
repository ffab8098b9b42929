#include "mesher/mesh_memo.h"

namespace mesher {

namespace {

template <typename T>
void append(std::string& key, const T& value) {
  key.append(reinterpret_cast<const char*>(&value), sizeof value);
}

}  // namespace

const MeshMemo::Entry* MeshMemo::find(const PolygonTree& built, int depth) {
  const TreeFrame& frame = built.frame;
  const QuadtreeInput& input = built.tree.input;
  key_.clear();
  if (capacity_ == 0) return nullptr;
  // Everything the tree and its meshing read: the origin and the turn only place the result.
  append(key_, depth);
  append(key_, frame.maxDepth);
  append(key_, frame.shortAxis);
  append(key_, frame.scale);
  append(key_, frame.stretch);
  append(key_, frame.rounding);
  append(key_, frame.gridSnap);
  for (const Vec2& v : input.vertices) append(key_, v);
  for (const auto& e : input.edges) append(key_, e);
  const auto found = entries_.find(key_);
  return found == entries_.end() ? nullptr : &found->second;
}

void MeshMemo::add(const std::vector<std::array<uint32_t, 4>>& elements, const std::vector<Vec2>& treePoints) {
  if (key_.empty() || !keeps(elements.size())) return;
  if (kept_ + elements.size() > capacity_) entries_.clear(), kept_ = 0;
  kept_ += elements.size();
  entries_.insert_or_assign(key_, Entry{elements, treePoints});
}

}  // namespace mesher
