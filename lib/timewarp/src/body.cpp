// The bodies of a world built from a scene (body.hpp).
#include <gjkx/timewarp/body.hpp>

#include <gjkx/dynamics/mass_properties.hpp>
#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/mesh/triangle_mesh.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gjkx {

template <typename S>
Shape<S> convexShapeOf(const ShapeSpec& spec, const std::vector<Eigen::Vector3d>& points) {
  using V = Eigen::Matrix<S, 3, 1>;
  switch (spec.kind) {
    case ShapeSpec::Kind::Box: return Box<S>(spec.halfExtents.cast<S>());
    case ShapeSpec::Kind::Sphere: return Sphere<S>(S(spec.radius));
    case ShapeSpec::Kind::Capsule:
      return Capsule<S>(V(0, 0, -S(spec.halfLength)), V(0, 0, S(spec.halfLength)), S(spec.radius));
    case ShapeSpec::Kind::Cylinder: return Cylinder<S>(S(spec.radius), S(spec.halfLength));
    case ShapeSpec::Kind::Polytope: {
      std::vector<V> cast;
      for (const auto& p : points) cast.push_back(p.cast<S>());
      return Polytope<S>::hull(cast);
    }
    case ShapeSpec::Kind::Mesh: break;
  }
  throw std::invalid_argument("a mesh is not a convex shape: its pieces are");
}

template <typename S>
std::vector<Shape<S>> piecesOf(const PieceSource& source) {
  if (!source.isMesh()) return {convexShapeOf<S>(source.convex, source.convex.points)};
  std::vector<Shape<S>> pieces;
  for (const auto& piece : source.meshPieces) {
    std::vector<Eigen::Matrix<S, 3, 1>> cast;
    for (const auto& p : piece) cast.push_back(p.cast<S>());
    pieces.push_back(source.meshPrisms ? Polytope<S>::prism(cast) : Polytope<S>::hull(cast));
  }
  return pieces;
}

template Shape<float> convexShapeOf<float>(const ShapeSpec&, const std::vector<Eigen::Vector3d>&);
template Shape<double> convexShapeOf<double>(const ShapeSpec&, const std::vector<Eigen::Vector3d>&);
template std::vector<Shape<float>> piecesOf<float>(const PieceSource&);
template std::vector<Shape<double>> piecesOf<double>(const PieceSource&);

namespace {

/// A static mesh met at the polygonal level, as the paper's plant is ("collision detection at
/// the polygonal level", §6): one convex piece per triangle, a thin prism under it (the
/// triangle and its copy moved back along its normal by a thousandth of the mesh's size),
/// so that a hull of neighbouring pieces has volume. A static body needs no volume of its
/// own, and a decomposition into hulls fills the space between thin leaves (the plant's
/// hulls by HACD came to 9 times its volume), where bodies would bounce off empty air.
ConvexDecomposition polygonPieces(const TriangleMesh& mesh) {
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double depth = 1e-3 * (hi - lo).norm();
  ConvexDecomposition out;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0)) continue;  // no area: no piece
    const Eigen::Vector3d back = -depth * n.normalized();
    out.pieces.push_back({a, b, c, a + back, b + back, c + back});
  }
  return out;
}

/// The density of a body spec: its `density`, or its `mass` over its volume (the mass at
/// density 1, `massAt(1)`).
template <typename MassAt>
double densityOf(const BodySpec& spec, MassAt&& massAt) {
  return spec.mass > 0 ? spec.mass / massAt(1.0) : spec.density;
}

/// A moving mesh's decomposition within its budget (the options' over the scene's), its
/// progress handed on and its report said once (a mesh is decomposed once per way it is used).
ConvexDecomposition decomposeReported(const TriangleMesh& mesh, DecompositionSettings settings, const std::string& name,
                                      const MeshBuildOptions& options) {
  if (options.budgetSeconds != 0) settings.budgetSeconds = options.budgetSeconds;  // a bad one is refused by name
  DecompositionObserver observer;
  if (options.progress) observer = [&](const DecompositionProgress& p) { options.progress(name, p); };
  ConvexDecomposition d = decompose(mesh, settings, options.cache, observer);
  const std::string line = describe(d.report, name);
  if (options.report) options.report(line, d.report);
  else std::fprintf(stderr, "gjkx: %s\n", line.c_str());
  return d;
}

std::string bodyField(const Scene& scene, const BodySpec& body, std::size_t index, const std::string& field) {
  return scene.source + ": body '" + body.name + "' (bodies[" + std::to_string(index) + "]): field '" + field + "'";
}

}  // namespace

std::vector<WorldBody> buildBodies(const Scene& scene, double duration, const std::string& meshCache) {
  MeshBuildOptions meshes;
  meshes.cache = meshCache;
  return buildBodies(scene, duration, meshes);
}

std::vector<WorldBody> buildBodies(const Scene& scene, double duration, const MeshBuildOptions& options) {
  // A mesh is read and decomposed once however many bodies use it alike (the
  // decomposition is also cached on disk, gjkx/mesh/convex_decomposition.hpp).
  std::map<std::string, std::pair<TriangleMesh, ConvexDecomposition>> meshes;
  std::vector<WorldBody> bodies;
  for (std::size_t index = 0; index < scene.bodies.size(); ++index) {
    const BodySpec& spec = scene.bodies[index];
    WorldBody body;
    body.name = spec.name;
    // The body frame is put at the centre of mass: free flight turns a body about it.
    Eigen::Vector3d centerOfMass = Eigen::Vector3d::Zero();
    MassProperties mass{};
    if (spec.shape.kind == ShapeSpec::Kind::Mesh) {
      const std::string& given = spec.shape.meshPath;
      const std::string path = !given.empty() && given[0] == '/' ? given : scene.folder + "/" + given;
      try {
        const ShapeSpec& shape = spec.shape;
        const bool hull = shape.meshCollision == ShapeSpec::MeshCollision::Hull;
        // A mesh is read and cut once per way it is used (the same file static and moving,
        // or at another scale, gives other pieces).
        std::ostringstream key;
        key << path << '|' << spec.isStatic << '|' << hull << '|' << shape.meshScale.transpose();
        auto found = meshes.find(key.str());
        if (found == meshes.end()) {
          // The file's node transforms applied, then the scene's scale.
          TriangleMesh mesh = readMesh(path, MeshRequirements{false, true});
          for (auto& v : mesh.vertices) v = v.cwiseProduct(shape.meshScale);
          // Checked before any decomposition, which can take seconds: a moving mesh cut into
          // pieces needs a volume (its mass), so it must be closed.
          if (!spec.isStatic && !hull) {
            try {
              validateMesh(mesh, MeshRequirements{true});
            } catch (const std::invalid_argument& e) {
              throw std::invalid_argument(std::string(e.what()) +
                                          " (a moving mesh to decompose must be closed; \"collision\": \"hull\" "
                                          "takes any mesh, open or closed, as its convex hull)");
            }
          }
          ConvexDecomposition pieces;
          if (hull) pieces.pieces = {mesh.vertices};  // one piece: the hull of every vertex
          else if (spec.isStatic) pieces = polygonPieces(mesh);
          else pieces = decomposeReported(mesh, shape.decomposition, given, options);
          found = meshes.emplace(key.str(), std::make_pair(std::move(mesh), std::move(pieces))).first;
        }
        const TriangleMesh& mesh = found->second.first;
        if (!spec.isStatic && hull) {  // the hull's own volume
          const Shape<double> hullShape = Polytope<double>::hull(mesh.vertices);
          mass = massProperties(hullShape, densityOf(spec, [&](double d) { return massProperties(hullShape, d).mass; }));
          centerOfMass = mass.centerOfMass;
          mass.centerOfMass = Eigen::Vector3d::Zero();
        } else if (!spec.isStatic) {  // the closed mesh's volume
          mass = polyhedronMassProperties(mesh.vertices, mesh.triangles, densityOf(spec, [&](double d) {
            return polyhedronMassProperties(mesh.vertices, mesh.triangles, d).mass;
          }));
          centerOfMass = mass.centerOfMass;
          mass.centerOfMass = Eigen::Vector3d::Zero();
        }
        std::vector<Eigen::Vector3d> all;
        body.source.meshPrisms = spec.isStatic && !hull;  // polygonPieces
        for (const auto& piece : found->second.second.pieces) {
          std::vector<Eigen::Vector3d> points;
          for (const auto& p : piece) points.push_back(p - centerOfMass);
          all.insert(all.end(), points.begin(), points.end());
          body.source.meshPieces.push_back(std::move(points));
        }
        body.pieces = piecesOf<double>(body.source);
        body.shape = Polytope<double>::hull(all);
      } catch (const std::exception& e) {
        throw std::invalid_argument(bodyField(scene, spec, index, "shape.mesh") + ": " + e.what());
      }
    } else {
      body.source.convex = spec.shape;
      try {
        const Shape<double> sceneShape = convexShapeOf<double>(spec.shape, spec.shape.points);
        if (!spec.isStatic) {
          mass = massProperties(sceneShape, densityOf(spec, [&](double d) { return massProperties(sceneShape, d).mass; }));
          centerOfMass = mass.centerOfMass;
          mass.centerOfMass = Eigen::Vector3d::Zero();
        }
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(bodyField(scene, spec, index, "shape") + ": " + e.what());
      }
      for (auto& p : body.source.convex.points) p -= centerOfMass;
      body.shape = convexShapeOf<double>(body.source.convex, body.source.convex.points);
      body.pieces = {body.shape};
    }
    body.frameOrigin = -centerOfMass;
    body.rigid = spec.isStatic ? RigidBody::fixed() : RigidBody::dynamic(mass);
    body.radius = body.shape.boundingRadius();
    BodyState start;
    start.worldFromBody.rotation = spec.orientation.toRotationMatrix();
    start.worldFromBody.translation = spec.position + start.worldFromBody.rotation * centerOfMass;
    start.velocity = spec.velocity;
    start.angularVelocity = spec.angularVelocity;
    // A static body is flown once, over the whole run: it is never integrated again.
    const double end = spec.isStatic ? duration : 0.0;
    body.setPath(freeFlight(body.rigid, start, 0.0, end, scene.gravity));
    bodies.push_back(std::move(body));
  }
  return bodies;
}

std::vector<VerifiedBody> verifiedBodies(const std::vector<WorldBody>& bodies) {
  std::vector<VerifiedBody> out;
  for (const WorldBody& body : bodies) out.push_back({body.name, body.pieces, body.shape, body.radius, body.rigid.isStatic()});
  return out;
}

}  // namespace gjkx
