// Running one of the project's programs as a user runs it, for the tests that check a
// program's output and exit status (gjkx_simulate, gjkx_bullet_scene, gjkx_mujoco_scene),
// and its SUMMARY line and CSV files read back.
#pragma once

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace test {

/// What a program did.
struct ProgramResult {
  int status = -1;     ///< the exit status (-1 when it did not exit normally)
  std::string output;  ///< standard output and standard error together
};

/// Runs `program` with `arguments` (a shell command line's tail) and collects its output.
inline ProgramResult runProgram(const std::string& program, const std::string& arguments) {
  const std::string command = "\"" + program + "\" " + arguments + " 2>&1";
  ProgramResult r;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

/// An empty folder of its own under the temporary folder: `prefix`-`name`-<process id>.
inline std::filesystem::path freshFolder(const std::string& prefix, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (prefix + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The keys of the SUMMARY line every peer's runner writes (chapters/08_torso/peer_run.hpp).
inline const std::vector<std::string>& peerSummaryKeys() {
  static const std::vector<std::string> keys = {"frames", "sim_s", "wall_s", "steps", "max_penetration",
                                                "tunnelled", "kinetic_start", "kinetic_end", "kinetic_max"};
  return keys;
}

/// The key=value pairs of the SUMMARY line of a program's `output` (empty if it has none).
inline std::map<std::string, double> summaryKeys(const std::string& output) {
  std::map<std::string, double> keys;
  const auto at = output.find("SUMMARY ");
  if (at == std::string::npos) return keys;
  std::stringstream line(output.substr(at + 8, output.find('\n', at) - at - 8));
  for (std::string item; line >> item;) {
    const auto eq = item.find('=');
    if (eq != std::string::npos) keys[item.substr(0, eq)] = std::stod(item.substr(eq + 1));
  }
  return keys;
}

/// The whole of a file, byte for byte (empty if it cannot be read).
inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The rows of a CSV file (the header first), split at commas.
inline std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream cellsIn(line);
    for (std::string cell; std::getline(cellsIn, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace test
