#include "mesher/mesher.h"

#include "mesher/balance.h"
#include "mesher/leaf_emitter.h"
#include "mesher/mesh_memo.h"
#include "mesher/quality_refinement.h"
#include "mesher/quadtree.h"

#include <optional>
#include <stdexcept>

namespace mesher {

size_t Mesh::quadCount() const {
  size_t quads = 0;
  for (const auto& e : elements) quads += e[3] != kNone;
  return quads;
}

Mesh meshPolygon(const PolygonWithHoles& polygon, const MeshSettings& settings) { return Mesher().mesh(polygon, settings); }

struct Mesher::State {
  explicit State(size_t remembered) : memo(remembered) {}
  PolygonTree built;
  std::optional<LeafEmitter> emitter;  // bound to `built`, made on first use
  std::optional<QualityRefiner> refiner;  // the same
  std::vector<int32_t> shortLeaves;        // LeafEmitter::collectShortLeaves
  MeshMemo memo;
  size_t repeats = 0;
};

Mesher::Mesher(size_t rememberedElements) : state_(std::make_unique<State>(rememberedElements)) {}
Mesher::~Mesher() = default;

size_t Mesher::repeats() const { return state_->repeats; }

size_t Mesher::quadrantsMade() const { return state_->built.tree.quadrantsMade; }

Mesh Mesher::mesh(const PolygonWithHoles& polygon, const MeshSettings& settings) {
  Mesh mesh;
  this->mesh(polygon, settings, mesh);
  return mesh;
}

void Mesher::mesh(const PolygonWithHoles& polygon, const MeshSettings& settings, Mesh& out) {
  State& s = *state_;
  // Phases of chapter 5: tree setup, edge storage and balancing, then splits of vertex leaves
  // that would mesh below the angle bound; then leaf by leaf meshing. A repeat of a polygon
  // met before takes its mesh, placed by its own frame.
  s.built.tree.quadrantBudget = settings.maxQuadrants;
  const int depth = setUpPolygonTree(polygon, settings.patchSize, s.built);
  if (const MeshMemo::Entry* repeat = s.memo.find(s.built, depth)) {
    out.vertices.assign(polygon.outer.begin(), polygon.outer.end());
    for (const Ring2& hole : polygon.holes) out.vertices.insert(out.vertices.end(), hole.begin(), hole.end());
    for (const Vec2& p : repeat->treePoints) out.vertices.push_back(s.built.frame.toPlane(p));
    out.elements.assign(repeat->elements.begin(), repeat->elements.end());
    ++s.repeats;
    return;
  }
  const int setUpMaxDepth = s.built.frame.maxDepth;
  buildMeshTree(polygon, settings.patchSize, s.built, s.refiner, depth);
  // Every node has four children, so about a quarter of the rest are nodes.
  const size_t leaves = (3 * s.built.tree.quadrants.size() + 1) / 4;
  if (!s.emitter) {
    s.emitter.emplace(polygon, s.built, leaves);
  } else {
    // The emitter fills the vertex memory `out` had (it handed over the last polygon's): a
    // second buffer of its own would be fresh pages once more.
    s.emitter->swapVertices(out.vertices);
    s.emitter->reset(polygon, leaves);
  }
  const bool keep = s.memo.keeps(leaves);
  s.emitter->keepTreePoints(keep);
  out.elements.clear();
  out.elements.reserve(leaves * 2);
  s.shortLeaves.clear();
  s.emitter->collectShortLeaves(&s.shortLeaves);
  s.emitter->emitAll(out.elements);
  s.emitter->collectShortLeaves(nullptr);
  // Leaves the refiner did not look at (without a vertex, or with one on their border) whose
  // regions fell short of the angle bound (rare: none in the shipped scenes) are split, and the
  // tree meshed again.
  if (!s.shortLeaves.empty() && s.refiner->splitShortLeaves(s.shortLeaves) > 0) {
    s.built.tree.changes.clear();
    s.emitter->reset(polygon, (3 * s.built.tree.quadrants.size() + 1) / 4);
    out.elements.clear();
    s.emitter->emitAll(out.elements);
  }
  if (keep && s.built.frame.maxDepth == setUpMaxDepth) s.memo.add(out.elements, s.emitter->treePoints());
  s.emitter->swapVertices(out.vertices);
}

}  // namespace mesher
