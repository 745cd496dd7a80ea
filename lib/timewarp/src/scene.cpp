// The scene file's parser: every field checked where it enters, every message naming the
// body and the field (scene.hpp lists the keys).
#include <gjkx/timewarp/scene.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace gjkx {

const char* orderingName(Ordering ordering) {
  switch (ordering) {
    case Ordering::Timewarp: return "timewarp";
    case Ordering::ToiHeap: return "toi_heap";
    case Ordering::FixedStep: return "fixed_step";
  }
  return "?";
}

const char* contactModelName(ContactModel model) {
  switch (model) {
    case ContactModel::Microcollisions: return "microcollisions";
    case ContactModel::Hybrid: return "hybrid";
  }
  return "?";
}

namespace {

using Json = nlohmann::json;

/// Where a value sits, for messages: "scene.json: body 'ball' (bodies[2]): field 'shape.sphere'".
struct Where {
  std::string source;
  std::string body;  // empty for the scene's own settings

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    std::string where = source + ": ";
    if (!body.empty()) where += body + ": ";
    throw std::invalid_argument(where + "field '" + field + "' " + what);
  }
};

void rejectUnknownKeys(const Json& object, const std::set<std::string>& known, const Where& where,
                       const std::string& prefix) {
  for (const auto& item : object.items()) {
    if (!known.count(item.key())) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      where.fail(prefix + item.key(), "is not a known key (known: " + list + ")");
    }
  }
}

double number(const Json& value, const Where& where, const std::string& field) {
  if (!value.is_number()) where.fail(field, "must be a number, got " + value.dump());
  const double x = value.get<double>();
  if (!std::isfinite(x)) where.fail(field, "must be finite, got " + value.dump());
  return x;
}

double positive(const Json& value, const Where& where, const std::string& field) {
  const double x = number(value, where, field);
  if (!(x > 0)) where.fail(field, "must be positive, got " + value.dump());
  return x;
}

double nonNegative(const Json& value, const Where& where, const std::string& field) {
  const double x = number(value, where, field);
  if (x < 0) where.fail(field, "must not be negative, got " + value.dump());
  return x;
}

Eigen::Vector3d vector3(const Json& value, const Where& where, const std::string& field) {
  if (!value.is_array() || value.size() != 3) where.fail(field, "must be an array of 3 numbers, got " + value.dump());
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k) v[k] = number(value[k], where, field + "[" + std::to_string(k) + "]");
  return v;
}

std::string text(const Json& value, const Where& where, const std::string& field) {
  if (!value.is_string()) where.fail(field, "must be a string, got " + value.dump());
  return value.get<std::string>();
}

// A mesh's "decomposition": HACD's settings that matter and the budget, each checked by name.
DecompositionSettings parseDecomposition(const Json& value, const Where& where) {
  const std::string field = "shape.decomposition";
  if (!value.is_object()) where.fail(field, "must be an object, got " + value.dump());
  rejectUnknownKeys(value,
                    {"budget_s", "concavity", "min_pieces", "compacity_weight", "volume_weight", "extra_points",
                     "face_points"},
                    where, field + ".");
  DecompositionSettings d;
  if (value.contains("budget_s")) d.budgetSeconds = positive(value["budget_s"], where, field + ".budget_s");
  if (value.contains("concavity")) d.concavity = positive(value["concavity"], where, field + ".concavity");
  if (value.contains("min_pieces")) {
    const Json& n = value["min_pieces"];
    if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 100000)
      where.fail(field + ".min_pieces", "must be an integer from 1 to 100000, got " + n.dump());
    d.minClusters = n.get<int>();
  }
  if (value.contains("compacity_weight"))
    d.compacityWeight = nonNegative(value["compacity_weight"], where, field + ".compacity_weight");
  if (value.contains("volume_weight")) d.volumeWeight = nonNegative(value["volume_weight"], where, field + ".volume_weight");
  for (const char* flag : {"extra_points", "face_points"}) {
    if (!value.contains(flag)) continue;
    if (!value[flag].is_boolean()) where.fail(field + "." + flag, "must be true or false, got " + value[flag].dump());
    (std::string(flag) == "extra_points" ? d.addExtraDistPoints : d.addFacesPoints) = value[flag].get<bool>();
  }
  return d;
}

ShapeSpec parseShape(const Json& value, const Where& where) {
  // A mesh takes options beside its path:
  // {"mesh": "path", "scale": s, "collision": "hull", "decomposition": {"budget_s": 10, ...}}.
  if (value.is_object() && value.contains("mesh") && value.size() > 1) {
    rejectUnknownKeys(value, {"mesh", "scale", "collision", "decomposition"}, where, "shape.");
    Json path = Json::object();
    path["mesh"] = value["mesh"];
    ShapeSpec shape = parseShape(path, where);
    if (value.contains("scale")) {
      const Json& s = value["scale"];
      if (s.is_number()) shape.meshScale = Eigen::Vector3d::Constant(positive(s, where, "shape.scale"));
      else if (s.is_array() && s.size() == 3)
        for (int k = 0; k < 3; ++k) shape.meshScale[k] = positive(s[k], where, "shape.scale[" + std::to_string(k) + "]");
      else where.fail("shape.scale", "must be a positive number or three, got " + s.dump());
    }
    if (value.contains("collision")) {
      const std::string c = text(value["collision"], where, "shape.collision");
      if (c == "decompose") shape.meshCollision = ShapeSpec::MeshCollision::Decompose;
      else if (c == "hull") shape.meshCollision = ShapeSpec::MeshCollision::Hull;
      else where.fail("shape.collision", "must be \"decompose\" or \"hull\", got \"" + c + "\"");
    }
    if (value.contains("decomposition")) shape.decomposition = parseDecomposition(value["decomposition"], where);
    return shape;
  }
  if (!value.is_object() || value.size() != 1)
    where.fail("shape", "must be an object with exactly one of box, sphere, capsule, cylinder, polytope, mesh; got " +
                            value.dump());
  const std::string kind = value.begin().key();
  const Json& spec = value.begin().value();
  ShapeSpec shape;
  const std::string field = "shape." + kind;
  if (kind == "box") {
    shape.kind = ShapeSpec::Kind::Box;
    shape.halfExtents = vector3(spec, where, field);
    for (int k = 0; k < 3; ++k)
      if (!(shape.halfExtents[k] > 0)) where.fail(field + "[" + std::to_string(k) + "]", "must be a positive half extent");
  } else if (kind == "sphere") {
    shape.kind = ShapeSpec::Kind::Sphere;
    shape.radius = positive(spec, where, field);
  } else if (kind == "capsule") {
    shape.kind = ShapeSpec::Kind::Capsule;
    if (!spec.is_array() || spec.size() != 2) where.fail(field, "must be [radius, half_length], got " + spec.dump());
    shape.radius = positive(spec[0], where, field + "[0] (radius)");
    shape.halfLength = nonNegative(spec[1], where, field + "[1] (half_length)");
  } else if (kind == "cylinder") {
    shape.kind = ShapeSpec::Kind::Cylinder;
    if (!spec.is_array() || spec.size() != 2) where.fail(field, "must be [radius, half_length], got " + spec.dump());
    shape.radius = positive(spec[0], where, field + "[0] (radius)");
    shape.halfLength = positive(spec[1], where, field + "[1] (half_length)");
  } else if (kind == "polytope") {
    shape.kind = ShapeSpec::Kind::Polytope;
    if (!spec.is_array() || spec.size() < 4) where.fail(field, "must be an array of at least 4 points [x, y, z]");
    for (std::size_t i = 0; i < spec.size(); ++i)
      shape.points.push_back(vector3(spec[i], where, field + "[" + std::to_string(i) + "]"));
  } else if (kind == "mesh") {
    shape.kind = ShapeSpec::Kind::Mesh;
    shape.meshPath = text(spec, where, field);
    if (shape.meshPath.empty()) where.fail(field, "must be a file path, got an empty string");
  } else {
    where.fail("shape." + kind, "is not a shape (known: box, sphere, capsule, cylinder, polytope, mesh)");
  }
  return shape;
}

BodySpec parseBody(const Json& value, std::size_t index, const std::string& source) {
  Where where{source, "bodies[" + std::to_string(index) + "]"};
  if (!value.is_object()) where.fail("", "must be an object, got " + value.dump());
  BodySpec body;
  if (!value.contains("name")) where.fail("name", "is missing");
  body.name = text(value["name"], where, "name");
  if (body.name.empty()) where.fail("name", "must not be empty");
  where.body = "body '" + body.name + "' (bodies[" + std::to_string(index) + "])";
  rejectUnknownKeys(value, {"name", "shape", "position", "orientation", "velocity", "angular_velocity", "density", "static",
                     "mass", "restitution", "friction"},
                    where, "");
  for (const char* required : {"shape", "position"})
    if (!value.contains(required)) where.fail(required, "is missing");
  body.shape = parseShape(value["shape"], where);
  body.position = vector3(value["position"], where, "position");
  if (value.contains("orientation")) {
    const Json& q = value["orientation"];
    if (!q.is_array() || q.size() != 4) where.fail("orientation", "must be a quaternion [w, x, y, z], got " + q.dump());
    Eigen::Vector4d wxyz;
    for (int k = 0; k < 4; ++k) wxyz[k] = number(q[k], where, "orientation[" + std::to_string(k) + "]");
    if (!(wxyz.norm() > 1e-12)) where.fail("orientation", "must not be the zero quaternion");
    wxyz.normalize();
    body.orientation = Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  }
  if (value.contains("velocity")) body.velocity = vector3(value["velocity"], where, "velocity");
  if (value.contains("angular_velocity"))
    body.angularVelocity = vector3(value["angular_velocity"], where, "angular_velocity");
  if (value.contains("density") && value.contains("mass"))
    where.fail("mass", "and 'density' are both given: a body takes one of the two");
  if (value.contains("density")) body.density = positive(value["density"], where, "density");
  if (value.contains("mass")) body.mass = positive(value["mass"], where, "mass");
  if (value.contains("restitution")) {
    body.restitution = number(value["restitution"], where, "restitution");
    if (body.restitution < 0 || body.restitution > 1) where.fail("restitution", "must lie in [0, 1]");
  }
  if (value.contains("friction")) body.friction = nonNegative(value["friction"], where, "friction");
  if (value.contains("static")) {
    if (!value["static"].is_boolean()) where.fail("static", "must be true or false, got " + value["static"].dump());
    body.isStatic = value["static"].get<bool>();
  }
  if (body.isStatic && (body.velocity.squaredNorm() > 0 || body.angularVelocity.squaredNorm() > 0))
    where.fail(body.velocity.squaredNorm() > 0 ? "velocity" : "angular_velocity",
               "must be zero (or left out) for a static body");
  return body;
}

}  // namespace

Scene parseScene(const std::string& textIn, const std::string& source) {
  Json root;
  try {
    root = Json::parse(textIn);
  } catch (const Json::exception& e) {  // a syntax error, or a number too large for a double (1e999)
    throw std::invalid_argument(source + ": not valid JSON: " + e.what());
  }
  const Where where{source, ""};
  if (!root.is_object()) where.fail("", "(the whole file) must be a JSON object");
  rejectUnknownKeys(root,
                    {"gravity", "frame_rate", "duration", "collision_tolerance", "restitution", "friction", "scalar",
                     "ordering", "fixed_substeps", "bodies", "contact", "solver"},
                    where, "");
  for (const char* required : {"duration", "bodies"})
    if (!root.contains(required)) where.fail(required, "is missing");
  Scene scene;
  if (root.contains("gravity")) scene.gravity = vector3(root["gravity"], where, "gravity");
  if (root.contains("frame_rate")) scene.frameRate = positive(root["frame_rate"], where, "frame_rate");
  scene.duration = positive(root["duration"], where, "duration");
  if (root.contains("collision_tolerance"))
    scene.collisionTolerance = positive(root["collision_tolerance"], where, "collision_tolerance");
  if (root.contains("restitution")) {
    scene.restitution = number(root["restitution"], where, "restitution");
    if (scene.restitution < 0 || scene.restitution > 1) where.fail("restitution", "must lie in [0, 1]");
  }
  if (root.contains("friction")) scene.friction = nonNegative(root["friction"], where, "friction");
  if (root.contains("scalar")) {
    const std::string s = text(root["scalar"], where, "scalar");
    if (s == "float") scene.run.scalar = CollisionScalar::Float;
    else if (s == "double") scene.run.scalar = CollisionScalar::Double;
    else where.fail("scalar", "must be \"float\" or \"double\", got \"" + s + "\"");
  }
  if (root.contains("ordering")) {
    const std::string s = text(root["ordering"], where, "ordering");
    if (s == "timewarp") scene.run.ordering = Ordering::Timewarp;
    else if (s == "toi_heap") scene.run.ordering = Ordering::ToiHeap;
    else if (s == "fixed_step") scene.run.ordering = Ordering::FixedStep;
    else where.fail("ordering", "must be \"timewarp\", \"toi_heap\" or \"fixed_step\", got \"" + s + "\"");
  }
  if (root.contains("fixed_substeps")) {
    const Json& n = root["fixed_substeps"];
    if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 100000)
      where.fail("fixed_substeps", "must be an integer from 1 to 100000, got " + n.dump());
    scene.run.fixedSubsteps = n.get<int>();
  }
  if (root.contains("solver")) {
    const std::string s = text(root["solver"], where, "solver");
    if (s == "paper") scene.run.solver = ToiSolverMode::Paper;
    else if (s == "gjkx") scene.run.solver = ToiSolverMode::Gjkx;
    else where.fail("solver", "must be \"paper\" or \"gjkx\", got \"" + s + "\"");
  }
  if (root.contains("contact")) {
    const std::string s = text(root["contact"], where, "contact");
    if (s == "microcollisions") scene.run.contact = ContactModel::Microcollisions;
    else if (s == "hybrid") scene.run.contact = ContactModel::Hybrid;
    else where.fail("contact", "must be \"microcollisions\" or \"hybrid\", got \"" + s + "\"");
  }
  const Json& bodies = root["bodies"];
  if (!bodies.is_array()) where.fail("bodies", "must be an array of bodies");
  if (bodies.empty()) where.fail("bodies", "must hold at least one body");
  scene.source = source;
  frameCount(scene);  // a duration whose frames do not fit is refused here, naming the field
  std::set<std::string> names;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    scene.bodies.push_back(parseBody(bodies[i], i, source));
    if (!names.insert(scene.bodies.back().name).second)
      Where{source, "bodies[" + std::to_string(i) + "]"}.fail("name", "'" + scene.bodies.back().name +
                                                                        "' is used by an earlier body");
  }
  return scene;
}

Scene loadScene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open the scene file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  Scene scene = parseScene(buffer.str(), path);
  const auto slash = path.find_last_of('/');
  scene.folder = slash == std::string::npos ? "." : path.substr(0, slash);
  return scene;
}

std::pair<double, double> materialOf(const Scene& scene, const BodySpec& a, const BodySpec& b) {
  const double ea = a.restitution >= 0 ? a.restitution : scene.restitution;
  const double eb = b.restitution >= 0 ? b.restitution : scene.restitution;
  const double mua = a.friction >= 0 ? a.friction : scene.friction;
  const double mub = b.friction >= 0 ? b.friction : scene.friction;
  return {std::max(ea, eb), mua == mub ? mua : std::sqrt(mua * mub)};
}

int frameCount(const Scene& scene) {
  constexpr double kMaxFrames = 1e8;
  const double frames = std::ceil(scene.duration * scene.frameRate - 1e-9);
  if (!(frames <= kMaxFrames))
    throw std::invalid_argument(scene.source + ": field 'duration': " + std::to_string(scene.duration) +
                                " s at frame_rate " + std::to_string(scene.frameRate) + " is " +
                                std::to_string(frames) + " frames, more than 10^8");
  return std::max(1, int(frames));
}

}  // namespace gjkx
