// The meshes of chapter 06: two real meshes nobody here wrote (Wuson and Spider from
// Debian's assimp-testmodels, BSD-3-Clause, installed by cmake/install-deps.sh) and a
// torus made here (nonconvex, closed). Shared by the figures and the benchmark.
#pragma once

#include <gjkx/mesh/convex_decomposition.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace chapter {

/// A named mesh of the chapter.
struct NamedMesh {
  std::string name;
  gjkx::TriangleMesh mesh;
};

/// A torus about the z axis: ring radius R, tube radius r, n x m quads split in two.
inline gjkx::TriangleMesh torus(double R, double r, int n, int m) {
  gjkx::TriangleMesh mesh;
  mesh.source = "torus";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      mesh.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto at = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

/// The chapter's meshes that are present (the real ones are skipped, with a message, if absent).
inline std::vector<NamedMesh> chapterMeshes() {
  std::vector<NamedMesh> out;
  const std::string models = "/usr/share/assimp/models";
  for (const auto& [name, path] : {std::pair<std::string, std::string>{"wuson", models + "/STL/Wuson.stl"},
                                   {"spider", models + "/STL/Spider_ascii.stl"}}) {
    if (std::filesystem::exists(path))
      out.push_back({name, gjkx::readMesh(path)});
    else
      std::fprintf(stderr, "%s: absent (Debian package assimp-testmodels), left out\n", path.c_str());
  }
  out.push_back({"torus", torus(1.0, 0.35, 48, 16)});
  return out;
}

}  // namespace chapter
