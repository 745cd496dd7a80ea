// gjkx_generate_torso: writes the scene of the paper's §6 experiment, a skeletal torso of
// 80 bones dropped from a random pose onto an aquatic plant (torso_model.hpp makes them).
//
//   gjkx_generate_torso --out DIR [--seed N] [--reduced]
//
// writes DIR/meshes/<bone>.off (one closed, outward-facing triangle mesh per bone, in the
// bone's own frame), DIR/plant.off and DIR/scene.json, a scene for gjkx_simulate with the
// paper's settings (24 frames a second, e = 0.7, mu = 0.4, tolerance sqrt(eps) of float,
// float, Timewarp) and a static floor. The seed chooses the drop: the torso's yaw, its
// tilt from upright and its offset over the plant; the same seed writes the same bytes.
// --reduced writes a small version (6 bones, 3 leaves, 1 s) for quick checks.
#include "../command_line.hpp"
#include "torso_model.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

namespace {

using torso::V3;

/// A number as the files write it: 9 significant digits, the same on every run.
std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x == 0 ? 0.0 : x);  // no "-0"
  return text;
}

/// Writes `mesh` as an OFF file.
void writeOff(const std::string& path, const gjkx::TriangleMesh& mesh) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot write the mesh");
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const V3& v : mesh.vertices) {
    out << number(v.x()) << ' ' << number(v.y()) << ' ' << number(v.z()) << '\n';
  }
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes the torso-and-plant scene of the paper's section 6: 80 bone meshes, the plant, scene.json.",
               "gjkx_generate_torso"};
  std::string out;
  std::uint32_t seed = 1;
  bool reduced = false;
  app.add_option("--out", out, "the folder to write meshes/, plant.off and scene.json into (created)")->required();
  app.add_option("--seed", seed, "chooses the drop pose (yaw, tilt, offset); same seed, same files")
      ->capture_default_str();
  app.add_flag("--reduced", reduced, "a small scene: 6 bones, 3 leaves, 1 s");
  chapter::parseOrExit(app, argc, argv);

  try {
    const torso::SceneLayout layout = torso::layoutScene(seed, reduced);
    const torso::Drop& drop = layout.drop;
    std::filesystem::create_directories(out + "/meshes");
    std::string json = "{\n  \"gravity\": [0, 0, -9.81],\n  \"frame_rate\": 24,\n  \"duration\": " +
                       number(layout.duration) +
                       ",\n  \"collision_tolerance\": 0.000345267,\n  \"restitution\": 0.7,\n  \"friction\": 0.4,\n"
                       "  \"scalar\": \"float\",\n  \"ordering\": \"timewarp\",\n  \"contact\": \"microcollisions\",\n  \"bodies\": [\n"
                       "    { \"name\": \"floor\", \"shape\": {\"box\": [" + number(torso::floorHalfWidth) + ", " +
                       number(torso::floorHalfWidth) + ", 0.1]}, \"position\": [0, 0, -0.1], "
                       "\"static\": true },\n"
                       "    { \"name\": \"plant\", \"shape\": {\"mesh\": \"plant.off\"}, \"position\": [0, 0, 0], "
                       "\"static\": true }";
    writeOff(out + "/plant.off", layout.plant);
    std::map<std::string, int> groups;
    long boneTriangles = 0;
    for (const auto& b : layout.bones) {
      writeOff(out + "/meshes/" + b.name + ".off", b.mesh);
      const V3& p = b.position;
      const Eigen::Quaterniond& q = b.orientation;
      json += ",\n    { \"name\": \"" + b.name + "\", \"shape\": {\"mesh\": \"meshes/" + b.name +
              ".off\"}, \"position\": [" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) +
              "], \"orientation\": [" + number(q.w()) + ", " + number(q.x()) + ", " + number(q.y()) + ", " +
              number(q.z()) + "], \"density\": 1500 }";
      ++groups[b.group];
      boneTriangles += long(b.mesh.triangles.size());
    }
    json += "\n  ]\n}\n";
    std::ofstream scene(out + "/scene.json", std::ios::binary);
    if (!scene || !(scene << json)) throw std::runtime_error(out + "/scene.json: cannot write the scene");

    std::printf("bones %zu:", layout.bones.size());
    for (const auto& [group, count] : groups) std::printf(" %s %d", group.c_str(), count);
    std::printf("\ntriangles bones=%ld plant=%zu\n", boneTriangles, layout.plant.triangles.size());
    std::printf("drop seed=%u yaw=%.1f deg tilt=%.1f deg offset=(%.3f, %.3f) m, lowest point %.3f m, plant top %.3f m\n",
                seed, drop.yaw * 180 / M_PI, drop.tilt * 180 / M_PI, drop.dx, drop.dy, drop.lowest, drop.plantTop);
    std::printf("wrote %s/scene.json\n", out.c_str());
  } catch (const std::exception& e) {
    std::cerr << "gjkx_generate_torso: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
