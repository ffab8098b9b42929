// Splits for element quality beyond the thesis: vertex leaves that do not mesh within the angle
// bound get a smaller leaf, or a finer leaf across a side, when that helps, and only then.
#include "mesher/quality_refinement.h"

#include "mesher/adaptive_mesh.h"
#include "mesher/balance.h"
#include "mesher/mesh_check.h"
#include "tests/mesher/mesh_expectations.h"
#include "tests/mesher/random_polygons.h"

#include <gtest/gtest.h>

#include <random>

namespace mesher {
namespace {

// A square of 4 x 4 leaves of edge 4 with its upper right part cut away: the reflex corner lies
// in leaf [4, 8]^2 at (fx, fy) of its edge. Near the lower side, the region left there is an L
// whose thin arm leaves the long lower side no element above the bound. The other corners lie
// on leaf sides, where nothing is split.
PolygonWithHoles notchCornerIn(double fx, double fy) {
  const double x = 4 + 4 * fx, y = 4 + 4 * fy;
  return {{{0, 0}, {16, 0}, {16, y}, {x, y}, {x, 16}, {0, 16}}, {}};
}

// Whether the leaf holding a corner (the reflex one, by default) meshes within the bound, as
// the refiner judges it (the emitter may still cut a ring that falls short).
bool cornerLeafReachesBound(const PolygonTree& built, Vec2 corner) {
  LeafRegionBuilder regions(built);
  const LeafRegion& region = regions.build(built.tree.leafAt(corner));
  std::vector<Vec2> ring;
  for (const RegionPoint& p : region.ring) ring.push_back(p.at);
  return SubdomainRemover().reachesBound(ring, region.hinge, &region.inner, built.frame.planePerTree(), &region.boundary, true,
                                         built.frame.rounding);
}
bool cornerLeafReachesBound(const PolygonTree& built) { return cornerLeafReachesBound(built, built.tree.input.vertices[3]); }

// The polygon meshes validly, with no element angle below the bound but at sharper input corners.
void expectMeshedWithinTheBound(const PolygonWithHoles& polygon, double patchSize) {
  const MeshCheck check = checkMesh(polygon, meshPolygon(polygon, {patchSize}));
  test::expectValidMesh(check);
  EXPECT_EQ(check.belowAngleBound, 0u);
  EXPECT_GE(check.smallestAngleDeg, kAngleBoundDeg);
}

TEST(QualityRefinement, AReflexCornerNearASideGetsASmallerLeaf) {
  const PolygonWithHoles polygon = notchCornerIn(0.8667, 0.1333);
  PolygonTree built = buildPolygonTree(polygon, 4);
  balance(built.tree);
  ASSERT_FALSE(cornerLeafReachesBound(built));
  EXPECT_GT(QualityRefiner(built).refine(), 0u);
  EXPECT_TRUE(cornerLeafReachesBound(built));

  expectMeshedWithinTheBound(polygon, 4);
}

// A reflex corner a hair (a five-hundredth of its leaf) above the leaf's lower side stays that
// close to the grid line however far its leaf is split, but twice as far, relatively, at each
// level down: the corner's leaf is split six levels and more, its surroundings graded with it,
// until the strip meshes within the bound. (Three levels left an element of 0.19 degrees.)
TEST(QualityRefinement, ACornerAHairFromASideIsSplitUntilTheStripMeshes) {
  const PolygonWithHoles polygon = notchCornerIn(0.6, 0.002);
  const PolygonTree built = buildMeshTree(polygon, {4});
  const Vec2 corner = built.tree.input.vertices[3];
  EXPECT_GE(built.tree[built.tree.leafAt(corner)].level, built.tree.uniformDepth + 6);
  EXPECT_TRUE(cornerLeafReachesBound(built, corner));

  expectMeshedWithinTheBound(polygon, 4);
}

// A random polygon with holes (the 20th of seed 2002) with a reflex corner 0.003% of its leaf
// from the leaf's west side: its leaf is split more than twelve levels. (Twelve at most left
// elements of 0 and 1.6 degrees there.)
TEST(QualityRefinement, ACornerAHairFromASideMaySplitMoreThanTwelveLevels) {
  const PolygonWithHoles polygon = test::randomTestPolygon(2002, false, 19).polygon;
  expectMeshedWithinTheBound(polygon, 24);
}

// A random polygon with holes (the 360th of seed 2016) whose vertices close together need a
// tree 16 levels below the patch size: a reflex corner 2% of its leaf from a side there is as
// deep as that tree goes. The mesher builds a tree 8 levels deeper, and the corner's leaf is
// split further. (Elements of 0.2 to 9 degrees were left there.)
TEST(QualityRefinement, ACornerAtTheDeepestLevelGetsADeeperTree) {
  const PolygonWithHoles polygon = test::randomTestPolygon(2016, false, 359).polygon;
  EXPECT_GT(buildMeshTree(polygon, {44}).tree.maxDepth, buildPolygonTree(polygon, 44).tree.maxDepth);
  expectMeshedWithinTheBound(polygon, 44);
}

// The Cornell box's floor with the tall block's footprint square to the walls: its corner
// (343, 332) lies 4.5 units from the side of a leaf 35 units on edge, and the strip between
// them leaves that side no element within the bound. Split, the leaf would put the corner a
// hair under a grid line; the leaf across is split instead, and its T-vertex at the side's
// middle anchors the strip. (Two elements were below the bound before.)
TEST(QualityRefinement, ACornerNearASideTakesAMidpointFromAcross) {
  const PolygonWithHoles floor{{{0, 0}, {556, 0}, {556, 559.2}, {0, 559.2}}, {{{213, 332}, {343, 332}, {343, 227}, {213, 227}}}};
  PolygonTree built = buildPolygonTree(floor, 60);
  balance(built.tree);
  const Vec2 corner = built.frame.toTree({343, 332});
  const uint8_t level = built.tree[built.tree.leafAt(corner)].level;
  ASSERT_FALSE(cornerLeafReachesBound(built, corner));
  EXPECT_GT(QualityRefiner(built).refine(), 0u);
  EXPECT_TRUE(cornerLeafReachesBound(built, corner));
  EXPECT_EQ(built.tree[built.tree.leafAt(corner)].level, level);

  const MeshCheck check = checkMesh(floor, meshPolygon(floor, {60}));
  test::expectValidMesh(check);
  EXPECT_EQ(check.belowAngleBound, 0u);
}

// The hole's corner (-396.9, -171.3) meshes within the bound as the tree is first built, and falls
// short once the splits for the other corners and for shallow wedges have put T-vertices beside
// it: vertex leaves are looked at again after later splits.
TEST(QualityRefinement, ACornerIsLookedAtAgainAfterSplitsBesideIt) {
  const PolygonWithHoles polygon{
      {{-333.63921598501474, -127.83153641546167}, {-403.84884126763853, -84.792851558933307},
       {-470.91442159146214, -168.97130268037037}, {-397.20958034560232, -229.02610203668993}},
      {{{-402.69761422439427, -169.38929832942119}, {-421.0422339876929, -162.22279468904196}, {-419.06069577269864, -181.17127793350494}},
       {{-402.97328383181491, -139.7086639859603}, {-413.50413540860518, -131.35154113106486}, {-423.50531620708301, -136.61759923014785},
        {-425.23569299124489, -143.53432115471171}, {-419.49903200156115, -152.57058007442413}, {-406.79944630274605, -151.52331442560427}},
       {{-374.41212344830433, -168.91756824126145}, {-393.14939749009062, -162.62591596140737}, {-396.89800150559842, -171.33340616064768},
        {-379.45528360180032, -180.62309494692187}}}};
  PolygonTree built = buildPolygonTree(polygon, 15);
  balance(built.tree);
  ASSERT_TRUE(cornerLeafReachesBound(built, built.frame.toTree(polygon.holes[2][2])));

  const MeshCheck check = checkMesh(polygon, meshPolygon(polygon, {15}));
  test::expectValidMesh(check);
  EXPECT_EQ(check.belowAngleBound, 0u);
}

// A random polygon with eight holes (the 492nd of seed 2010) whose vertex leaves are split in
// six passes, each pass's splits changing leaves beside vertices looked at before. With three
// passes at most, a corner 1.2% of its leaf from a side was left with an element of 1 degree.
TEST(QualityRefinement, VertexLeavesAreLookedAtAgainUntilNoSplitChangesThem) {
  const PolygonWithHoles polygon = test::randomTestPolygon(2010, false, 491).polygon;
  expectMeshedWithinTheBound(polygon, 16);
}

// A wedge handed over up to the giver's own vertex leaves the giver running from the vertex
// straight to a grid point on its side (wedge_handover.h). The hole's corner (-331.5, 81.2) lies
// 0.6% of its leaf from the leaf's east side, so the ring's corner at that grid point had 13
// degrees, which the ring's meshing cannot help; smaller leaves put a grid point nearer the
// vertex, and the refiner now takes such a corner as falling short.
TEST(QualityRefinement, AGridPointCornerLeftByAHandoverIsRefined) {
  const PolygonWithHoles polygon{
      {{-314.06653419918081, 72.796216570603605}, {-328.02319670798249, 92.026289331847735}, {-345.64318118465178, 90.39366181577374},
       {-355.87392248884208, 69.222904700149712}, {-339.94878762470051, 51.786476243340132}, {-321.91098407001641, 55.846730829283302}},
      {{{-327.51578984015947, 66.137488491473306}, {-334.68733377604451, 62.528984810670188}, {-343.20049564503074, 66.917952292071789},
        {-343.90069026806481, 76.270858120719822}, {-340.96261237428263, 79.94705600821797}, {-331.45650864726468, 81.237286007626594},
        {-325.81542676417826, 75.146130793982195}}}};
  expectMeshedWithinTheBound(polygon, 42);
}

// The same handover gives the leaf across a corner at the vertex itself, between the vertex's
// other edge and the line from it to the grid point: here 5 degrees where the polygon's corner
// (21.1, -2.8) has 124. Such a corner, sharper in the ring than in the polygon, counts as falling
// short too.
TEST(QualityRefinement, AVertexCornerSharperInItsRingThanInThePolygonIsRefined) {
  const PolygonWithHoles polygon{
      {{18.69522813214131, 1.6049949436743911}, {15.172714530498331, 9.5075233395777801}, {22.370507010160598, 26.360144235316383},
       {7.34276572519064, 26.946348526554118}, {-0.2033018961070141, 27.057677133574156}, {-6.7539461909702343, 12.22389371086399},
       {-17.299245500442531, 14.286386286959463}, {-32.000798224199677, 9.9054267440405876}, {-20.391497851618357, -0.53473979997398158},
       {-24.949282909312704, -14.44971228840391}, {-7.0090454721531561, -12.544819109604035}, {-3.0946279611656196, -32.215150475881856},
       {6.2882368486799098, -30.947807940024799}, {20.278180470085182, -26.93947912182982}, {16.289587152424964, -12.354747204838317},
       {21.148065555882891, -2.777097994854985}},
      {{{6.0321046445856616, 0.53119542620525162}, {4.6141455107213831, 1.361373889535501}, {3.533324393138594, -0.62986109570155957},
        {5.1432363607588032, -1.334039727976037}},
       {{-0.82183176931115831, 0.43125166659059044}, {-2.4672159733874803, 1.3271624576225924}, {-3.5051157892131251, -0.070072329750833898},
        {-2.0107859229656371, -1.3822617574504754}}}};
  expectMeshedWithinTheBound(polygon, 12);
}

// The hole's corner (155.6, 436.2) lies 39% of its leaf from the nearest side, where no thin
// strip can be, yet the shallow edges beside it left its ring an element of 7 degrees: every
// vertex inside its leaf is looked at, not only those near a side.
TEST(QualityRefinement, AVertexWellInsideItsLeafIsLookedAtToo) {
  const PolygonWithHoles polygon{
      {{233.20445492694779, 477.58930919158252}, {185.40976269258314, 532.08863970859579}, {108.32375952247315, 505.09476136531237},
       {112.71135539348529, 421.51528487547102}, {202.12517301148384, 407.95256997498313}},
      {{{158.222634693446, 457.26821948111416}, {140.11342991501189, 460.79859484755553}, {132.46025719651129, 447.22988050626725},
        {155.60390526581057, 436.20143756206954}},
       {{197.43143939556433, 451.99977536737987}, {184.13503133389906, 462.51761189560574}, {170.95085761468971, 455.47994451510806},
        {169.65794118308528, 443.22075415025813}, {176.87661049241206, 434.95537432050742}, {192.78801587759946, 436.79803455603582}},
       {{197.18695792420672, 489.18959223990612}, {173.28836075832896, 494.84471465837584}, {169.15576161777287, 481.48442955756161},
        {192.23206778180662, 472.77681243528724}}}};
  expectMeshedWithinTheBound(polygon, 43);
}

// A leaf holding no vertex, cut by one edge below a T-vertex on its west side, left its region a
// long four-sided strip that no meshing brought to the bound (17 degrees). Leaves without a
// vertex are not looked at beforehand; the mesher splits those whose meshing fell short and
// meshes again, and an adaptive mesh starts as that same mesh.
TEST(QualityRefinement, ALeafWithoutAVertexThatFallsShortIsSplit) {
  const PolygonWithHoles polygon{
      {{19.838411291130505, 2.6896953562542576}, {18.639515499988196, 28.813334206185615}, {3.8520634040991983, 14.496988954084419},
       {-7.4988203734972458, 14.182917872172855}, {-33.181677571037618, -0.017206254900960616}, {-35.005509712670495, -19.959287410408333},
       {-32.69001443441347, -37.989203253964064}, {-11.573936114465768, -42.143932703299242}, {8.573608650127861, -28.825129544325051},
       {27.607735811932084, -15.82168962107334}},
      {}};
  expectMeshedWithinTheBound(polygon, 6);
  const AdaptiveMesh adaptive(polygon, {6});
  const Mesh whole = meshPolygon(polygon, {6});
  EXPECT_EQ(adaptive.vertices(), whole.vertices);
  EXPECT_EQ(adaptive.elements().size(), whole.elements.size());
  EXPECT_EQ(checkMesh(polygon, adaptive.snapshot()).belowAngleBound, 0u);
}

// A corner a hair from a grid line stays that close to one, relatively, for more levels than
// splitting may go: the tree's leaves are left as they were.
TEST(QualityRefinement, SplitsThatDoNotHelpAreTakenBack) {
  PolygonTree built = buildPolygonTree(notchCornerIn(0.8667, 1e-7), 4);
  balance(built.tree);
  ASSERT_FALSE(cornerLeafReachesBound(built));
  const size_t leaves = built.tree.leaves().size();
  EXPECT_EQ(QualityRefiner(built).refine(), 0u);
  EXPECT_EQ(built.tree.leaves().size(), leaves);
}

// The spike's tip (-2.782, -15.9427) lies in a leaf that would take a shallow wedge and is split
// for it; near the tip its two edges run closer together than the finest leaf, so the split ran
// out of depth part way and was kept so: the tip's leaf lost its vertex, the leaves beside it
// one edge, and the mesh had T-vertices and unmatched edges. Such a split is taken back, and
// the tree built again deeper, where the taker splits and takes the wedge (17.5 degrees before).
TEST(QualityRefinement, ASplitThatRunsOutOfDepthIsTakenBack) {
  const PolygonWithHoles spike{{{70.27, 29.2}, {46, 34}, {30.1358, 21.231}, {10.7905, 47.2521}, {21, 22}, {19, -2}, {-2.782, -15.9427},
                                {21, -7.7}, {9, -26}, {10.985, -42.57}, {39, -38}, {69.23, -36.655}, {68, -6}, {64, 1}},
                               {}};
  const PolygonTree built = buildMeshTree(spike, {23});
  const Vec2 tip = built.tree.input.vertices[6];
  EXPECT_EQ(built.tree[built.tree.leafAt(tip)].vertex, 6);
  EXPECT_GT(built.tree.maxDepth, buildPolygonTree(spike, 23).tree.maxDepth);
  const MeshCheck check = checkMesh(spike, meshPolygon(spike, {23}));
  test::expectValidMesh(check);
  EXPECT_EQ(check.belowAngleBound, 0u);  // the tip itself is sharper than the bound
}

// A random star polygon 1e5 from the origin (the 422nd of seed 12003) with a vertex on the east
// side of a coarsest leaf: the leaf's region, a strip between its closed south side and an edge
// meeting that side's line at 16.8 degrees, fell short (15 degrees). Vertices on their leaf's
// border are not looked at beforehand; meshed short, the leaf is split and meshed again.
TEST(QualityRefinement, AVertexOnItsLeafsBorderThatFallsShortIsSplit) {
  const test::RandomTestPolygon star = test::randomTestPolygon(12003, true, 421);
  const MeshCheck check = checkMesh(star.polygon, meshPolygon(star.polygon, {star.patchSize}));
  test::expectValidMesh(check);
  EXPECT_EQ(check.belowAngleBound, 0u);
  const AdaptiveMesh adaptive(star.polygon, {star.patchSize});
  EXPECT_EQ(checkMesh(star.polygon, adaptive.snapshot()).belowAngleBound, 0u);
}

// The refined trees stay 2:1 balanced (AdaptiveMesh builds on them), and splits happen.
TEST(QualityRefinement, RefinedTreesStayBalanced) {
  std::mt19937 random(31);
  size_t splits = 0;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);
    const PolygonWithHoles polygon = trial % 2 ? test::randomStarPolygon(random, trial) : test::randomPolygonWithHoles(random, trial);
    PolygonTree built = buildPolygonTree(polygon, 3 + trial % 17);
    balance(built.tree);
    splits += QualityRefiner(built).refine();
    built.tree.changes.clear();
    EXPECT_EQ(balance(built.tree), 0u);
  }
  EXPECT_GT(splits, 0u);
}

}  // namespace
}  // namespace mesher
