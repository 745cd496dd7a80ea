// Writes the resting scenes the hybrid contact model is measured on (docs/07_timewarp.md,
// *Resting contact*), as scene files that gjkx_simulate and gjkx_bullet_scene both run:
// a pyramid of boxes (`--rows N`: N(N+1)/2 boxes of 1 m, each row on the gaps of the one
// below, 1 mm apart sideways and 0.1 mm above) or a stack (`--stack N`), on a static floor.
#include "../command_line.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  CLI::App app{"Writes a pyramid or a stack of boxes resting on a floor as a gjkx scene file.",
               "gjkx_generate_pyramid"};
  int rows = 20, stack = 0;
  double duration = 10;
  std::string out, contact = "hybrid";
  app.add_option("--rows", rows, "rows of the pyramid (N(N+1)/2 boxes)")->check(CLI::Range(1, 200))->capture_default_str();
  app.add_option("--stack", stack, "a stack of this many boxes instead of a pyramid")->check(CLI::Range(1, 1000));
  app.add_option("--duration", duration, "simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--contact", contact, "the scene's contact model")
      ->check(CLI::IsMember({"hybrid", "microcollisions"}))
      ->capture_default_str();
  app.add_option("--out", out, "the scene file to write")->required();
  chapter::parseOrExit(app, argc, argv);
  std::string bodies = R"(    { "name": "floor", "shape": {"box": [60, 60, 0.5]}, "position": [0, 0, -0.5], "static": true })";
  char line[256];
  const auto box = [&](const std::string& name, double x, double z) {
    std::snprintf(line, sizeof line, R"(,
    { "name": "%s", "shape": {"box": [0.5, 0.5, 0.5]}, "position": [%.6f, 0, %.6f] })",
                  name.c_str(), x, z);
    bodies += line;
  };
  if (stack > 0) {
    for (int k = 0; k < stack; ++k) box("box" + std::to_string(k), 0, 0.5001 + k * 1.0001);
  } else {
    for (int row = 0; row < rows; ++row)
      for (int k = 0; k < rows - row; ++k)
        box("p" + std::to_string(row) + "_" + std::to_string(k), (k - 0.5 * (rows - 1 - row)) * 1.001,
            0.5001 + row * 1.0001);
  }
  std::ofstream file(out);
  file << "{\n  \"duration\": " << duration << ",\n  \"restitution\": 0.5,\n  \"friction\": 0.5,\n  \"contact\": \""
       << contact << "\",\n  \"bodies\": [\n" << bodies << "\n  ]\n}\n";
  if (!file) {
    std::cerr << "gjkx_generate_pyramid: cannot write " << out << "\n";
    return 1;
  }
  return 0;
}
