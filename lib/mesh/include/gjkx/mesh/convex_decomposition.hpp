/// @file
/// @brief Convex decomposition of a nonconvex mesh into convex pieces, through HACD, cached on disk (§6).
///
/// §6: each nonconvex surface is cut into convex pieces; GJK and the extrusion test then
/// run on pieces, and a hierarchy of 14-DOPs (stage `kdop`) prunes the piece pairs.
/// The decomposition is not the paper's subject, so a kept library computes it: HACD
/// (Mamou and Ghorbel's hierarchical approximate convex decomposition, shipped by Debian
/// in `libbullet-extras-dev`). HACD returns a partition of the triangles into clusters; the
/// piece of a cluster is the convex hull of its triangles' vertices, built by Qhull
/// (`convexHull3d`), so every piece is exactly the hull of surface points and the pieces
/// together cover the surface. Each piece becomes a `Polytope` with hill climbing.
///
/// HACD cannot be stopped from inside (its call-back's answer is ignored, and its merging
/// loop never looks at a clock; a sphere of 134 vertices has kept it busy for minutes), so it
/// runs in a forked worker (forked_worker.hpp) with a budget of wall time. When the budget
/// runs out, or the worker fails, the mesh's convex hull is its one piece, and standard error
/// says so, naming the mesh and the time spent.
#pragma once

#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gjkx {

/// HACD's settings (names as in HACD's own interface, `hacdHACD.h`).
struct DecompositionSettings {
  /// The number of clusters HACD stops merging at, at least (HACD's `SetNClusters`).
  int minClusters = 1;
  /// The largest concavity a merged cluster may have, in HACD's normalised units (the
  /// mesh scaled to `scale`; HACD's `SetConcavity`). Smaller: more, tighter pieces.
  double concavity = 100.0;
  /// HACD's normalisation size (`SetScaleFactor`).
  double scale = 1000.0;
  /// The largest number of vertices HACD keeps per hull while merging (`SetNVerticesPerCH`).
  int maxVerticesPerHull = 100;
  /// Weight of the compactness term of the merge cost (`SetCompacityWeight`).
  double compacityWeight = 0.1;
  /// Weight of the volume term of the merge cost (`SetVolumeWeight`).
  double volumeWeight = 0.0;
  /// Also measure concavity at extra points along normals (`SetAddExtraDistPoints`): better
  /// pieces on thin parts, slower.
  bool addExtraDistPoints = true;
  /// Also measure concavity at face centres (`SetAddFacesPoints`).
  bool addFacesPoints = true;
  /// Seconds of wall time HACD may take; after them it is stopped and the mesh's convex hull
  /// is its one piece (`DecompositionReport::fellBack`). Not part of the cache key: a budget
  /// does not change the pieces of a decomposition that finishes within it.
  double budgetSeconds = 30.0;
  /// Throws std::invalid_argument naming the field for a value out of range.
  void validate() const;
};

/// What a decomposition looks like, per mesh (§6: how good the pieces are).
struct DecompositionReport {
  /// The number of convex pieces.
  int pieces = 0;
  /// Hull vertices of each piece.
  std::vector<int> verticesPerPiece;
  /// True if the mesh is closed (every edge on two triangles, consistently oriented).
  bool meshClosed = false;
  /// The volume the mesh encloses (`enclosedVolume`); for an open mesh, the volume of the
  /// cones from the vertices' centroid to its triangles, an approximation that ignores the holes.
  double meshVolume = 0;
  /// The sum of the pieces' hull volumes.
  double hullVolume = 0;
  /// \f$(\sum V_{hull} - V_{mesh}) / V_{mesh}\f$: how much the hulls add to the body (overlaps
  /// of neighbouring hulls count twice); NaN when the mesh volume is 0.
  double volumeExcess = 0;
  /// True when the pieces were read from the cache instead of computed.
  bool fromCache = false;
  /// The cache file (empty when caching was off).
  std::string cacheFile;
  /// Seconds HACD took (0 when read from the cache); with a fallback, the seconds spent before it.
  double seconds = 0;
  /// True when the decomposition did not finish (its budget ran out, or HACD failed) and the
  /// mesh's convex hull is its one piece instead.
  bool fellBack = false;
  /// Why it fell back ("the budget of 30 s ran out", "HACD died of signal 11 (...)"); empty otherwise.
  std::string fallbackReason;
};

/// One line that tells a user what became of a mesh: its pieces, the vertices per piece
/// (fewest, mean, most), the volume excess and the time, or "(cached)", or the fallback and
/// why; `name` names the mesh (its file).
std::string describe(const DecompositionReport& report, const std::string& name);

/// How far a running decomposition has come, for a progress bar.
struct DecompositionProgress {
  /// What HACD is doing: "graph" (the dual graph of the triangles and their concavity
  /// points), "costs" (the cost of every possible merge), "merging" (the merges), "hulls";
  /// last, once, "done" (whether it finished or not: a progress bar ends its line).
  const char* phase = "";
  /// How much of that phase is done, 0 to 1 (merging: the share of triangles merged away,
  /// which stops short of 1 when the concavity bound is met first; costs: 0, unknown).
  double fraction = 0;
  /// Seconds since the decomposition started.
  double seconds = 0;
  /// Its budget in seconds (DecompositionSettings::budgetSeconds).
  double budgetSeconds = 0;
};

/// Called about ten times a second while HACD runs (in the calling process; HACD runs in a
/// worker), for a progress bar.
using DecompositionObserver = std::function<void(const DecompositionProgress&)>;

/// The convex pieces of a mesh: for each, the vertices of its convex hull (in the mesh's
/// frame, double precision), with the report.
struct ConvexDecomposition {
  /// The hull vertices of each piece.
  std::vector<std::vector<Eigen::Vector3d>> pieces;
  /// For each triangle of the mesh, the piece it belongs to (HACD's partition).
  std::vector<int> pieceOfTriangle;
  /// Pieces, vertices per piece, volume excess.
  DecompositionReport report;

  /// Each piece as a `Polytope` of the `support_mapping` stage (Qhull hull, hill climbing).
  template <typename S>
  std::vector<Polytope<S>> polytopes() const {
    std::vector<Polytope<S>> out;
    out.reserve(pieces.size());
    for (const auto& piece : pieces) {
      std::vector<Vector3<S>> points;
      points.reserve(piece.size());
      for (const auto& p : piece) points.push_back(p.cast<S>());
      out.push_back(Polytope<S>::hull(points));
    }
    return out;
  }
};

/// The folder the decomposition cache uses by default, where caches go: the environment
/// variable `GJKX_MESH_CACHE` if set (empty: no cache), else `$XDG_CACHE_HOME/gjkx`, else
/// `$HOME/.cache/gjkx`, else none (an empty string: caching off). Nothing compiled in: an
/// installed program never writes into the tree it was built in.
std::string defaultDecompositionCacheDir();

/// A 64-bit hash (FNV-1a) of a mesh's vertices and triangles and the settings: the
/// cache key. Equal meshes and settings give equal keys on every run.
std::uint64_t decompositionKey(const TriangleMesh& mesh, const DecompositionSettings& settings);

/// Decomposes `mesh` into convex pieces with HACD, or reads the pieces from
/// `cacheDir/<key>.pieces` when an earlier run computed them (an empty `cacheDir` turns
/// caching off; a folder that cannot be made or written degrades to no cache, with one
/// warning on standard error per process). HACD runs in a forked worker for at most
/// `settings.budgetSeconds`, calling `observer` as it goes; a decomposition that does not
/// finish falls back to the mesh's convex hull (one piece, every triangle in it), says so on
/// standard error, and is remembered in `cacheDir/<key>.fallback` with its budget, so that
/// a later run with no larger a budget falls back at once. The mesh is validated first (`validateMesh`; real meshes often have holes,
/// so closure is not required, but the report says whether the mesh is closed):
/// std::invalid_argument names the mesh's source and the fault. A cluster whose
/// vertices lie in one plane (no volume) is thickened by \f$10^{-6}\f$ of the mesh's
/// diagonal along its normal so that it still has a hull.
ConvexDecomposition decompose(const TriangleMesh& mesh, const DecompositionSettings& settings = {},
                              const std::string& cacheDir = defaultDecompositionCacheDir(),
                              const DecompositionObserver& observer = {});

/// The volume of a convex hull given by its vertices (Qhull hull, divergence theorem).
double hullVolume(const std::vector<Eigen::Vector3d>& points);

}  // namespace gjkx
