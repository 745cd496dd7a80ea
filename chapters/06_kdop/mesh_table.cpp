// gjkx_mesh_table: every model of Debian's assimp-testmodels that Assimp reads, tried as a
// user's moving body, written as the Markdown table docs 06 includes.
//
//   gjkx_mesh_table --out figures/data/assimp-meshes.md [--models DIR] [--budget SECONDS]
//
// For each file under DIR (default /usr/share/assimp/models), in the order of their paths:
// read as gjkx_simulate reads a scene's mesh (gjkx::readMesh, the file's node transforms
// applied); a file Assimp cannot read (an image, a material, a format it lacks) is left out
// and counted. Each model is then made a moving body of a scene twice, through
// gjkx::buildBodies as gjkx_simulate builds it, with no mesh cache:
// - `{"mesh": path}`, the default collision: convex pieces by HACD within the budget, or
//   refused at once when the mesh is not closed, or the mesh's hull when the budget runs out;
// - `{"mesh": path, "collision": "hull"}`: its convex hull, one piece.
// A row says what became of it: decomposed (pieces, hull vertices per piece, volume excess,
// seconds), its hull after the budget, or refused with gjkx's message. Each model runs in a
// forked worker (gjkx::runForked) with a limit, so that a test model that crashes Assimp or
// never finishes becomes a row instead of ending the table.
#include "../command_line.hpp"

#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/mesh/forked_worker.hpp>
#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

/// One way of making a model a body, as the table shows it.
struct Attempt {
  std::string result;   ///< "decomposed", "hull after the budget", "hull", or "refused: <why>"
  int pieces = 0;       ///< convex pieces of the body
  int fewest = 0;       ///< hull vertices of its smallest piece
  int most = 0;         ///< and of its largest
  double excess = NAN;  ///< the pieces' volumes over the mesh's, minus one
  double seconds = 0;   ///< wall time of buildBodies
};

/// What the worker found for one model.
struct Row {
  std::string path;     ///< relative to the models' folder
  bool readable = true;  ///< Assimp read it (else the row is left out)
  std::string unread;   ///< why not, if not
  int triangles = 0, vertices = 0;
  bool closed = false;
  Attempt decompose, hull;
};

/// gjkx's message without the scene's own prefix (this program's made-up scene and body)
/// and with the model's folder taken off its path: what a user would read about the file.
std::string cleaned(std::string message, const std::string& folder) {
  const std::string field = "field 'shape.mesh': ";
  if (const auto at = message.find(field); at != std::string::npos) message.erase(0, at + field.size());
  for (std::size_t at; (at = message.find(folder + "/")) != std::string::npos;) message.erase(at, folder.size() + 1);
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '|', '/');  // a Markdown cell
  if (message.size() > 160) message = message.substr(0, 157) + "...";
  return message;
}

/// The model as a moving body of a one-body scene, built as gjkx_simulate builds it.
Attempt attempt(const std::string& path, bool asHull, double budget, const gjkx::TriangleMesh& mesh,
                const std::string& folder) {
  std::string quoted = "\"";  // the path as a JSON string
  for (const char c : path) quoted += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  quoted += "\"";
  const std::string scene = R"({ "duration": 1, "bodies": [ { "name": "model", "shape": {"mesh": )" + quoted +
                            (asHull ? R"(, "collision": "hull")" : "") + R"(}, "position": [0, 0, 0] } ] })";
  gjkx::MeshBuildOptions options;
  options.cache = "";  // every row measured, none read back
  options.budgetSeconds = budget;
  gjkx::DecompositionReport report;
  bool reported = false;
  options.report = [&](const std::string&, const gjkx::DecompositionReport& r) {
    report = r;
    reported = true;
  };
  Attempt a;
  const auto start = std::chrono::steady_clock::now();
  try {
    const std::vector<gjkx::WorldBody> bodies = gjkx::buildBodies(gjkx::parseScene(scene, "table"), 1.0, options);
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (reported) {
      a.result = report.fellBack ? "hull after the budget" : "decomposed";
      a.pieces = report.pieces;
      a.fewest = *std::min_element(report.verticesPerPiece.begin(), report.verticesPerPiece.end());
      a.most = *std::max_element(report.verticesPerPiece.begin(), report.verticesPerPiece.end());
      a.excess = report.volumeExcess;
    } else {  // the hull: one piece; its excess over the mesh's volume as the report measures it
      a.result = "hull";
      const auto& piece = std::get<gjkx::Polytope<double>>(bodies[0].pieces[0].variant());
      a.pieces = 1;
      a.fewest = a.most = piece.vertexCount();
      const double meshVolume = std::abs(gjkx::enclosedVolume(mesh));
      a.excess = meshVolume > 0 ? gjkx::hullVolume(piece.vertices()) / meshVolume - 1 : NAN;
    }
  } catch (const std::exception& e) {
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    a.result = "refused: " + cleaned(e.what(), folder);
  }
  return a;
}

// The worker's answer crosses a pipe as lines: the row's fields in a fixed order.
void put(std::ostream& out, const Attempt& a) {
  out << a.result << '\n' << a.pieces << ' ' << a.fewest << ' ' << a.most << ' ' << a.excess << ' ' << a.seconds << '\n';
}

bool get(std::istream& in, Attempt& a) {
  std::string excess;
  if (!std::getline(in, a.result) || !(in >> a.pieces >> a.fewest >> a.most >> excess >> a.seconds)) return false;
  a.excess = excess == "nan" || excess == "-nan" ? NAN : std::stod(excess);
  in.ignore(1, '\n');
  return true;
}

/// Reads one model and tries it both ways, in the worker.
std::string measure(const std::string& folder, const std::string& relative, double budget) {
  const std::string path = folder + "/" + relative;
  std::ostringstream out;
  gjkx::TriangleMesh mesh;
  try {
    mesh = gjkx::readMesh(path, gjkx::MeshRequirements{false, true});
  } catch (const std::runtime_error& e) {  // Assimp could not read it: not a model of the table
    out << "unread\n" << cleaned(e.what(), folder) << '\n';
    return out.str();
  } catch (const std::exception& e) {  // read, but refused by gjkx: a row of the table, refused both ways
    Attempt refused;
    refused.result = "refused: " + cleaned(e.what(), folder);
    out << "read\n0 0 0\n";
    put(out, refused);
    put(out, refused);
    return out.str();
  }
  bool closed = true;
  try {
    gjkx::validateMesh(mesh, gjkx::MeshRequirements{true});
  } catch (const std::invalid_argument&) {
    closed = false;
  }
  out << "read\n" << mesh.triangles.size() << ' ' << mesh.vertices.size() << ' ' << closed << '\n';
  put(out, attempt(path, false, budget, mesh, folder));
  put(out, attempt(path, true, budget, mesh, folder));
  return out.str();
}

std::string number(double x, const char* format) {
  if (!std::isfinite(x)) return "–";
  if (std::abs(x) < 1e-9) x = 0;  // no "-0.0"
  char text[32];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

std::string cells(const Attempt& a, bool withPieces) {
  std::string out = a.result + " | ";
  const bool made = a.result.rfind("refused", 0) != 0;
  if (withPieces) out += made ? std::to_string(a.pieces) + " (" + std::to_string(a.fewest) + "–" + std::to_string(a.most) + ")" : "";
  else out += made ? std::to_string(a.most) : "";
  const double percent = std::abs(a.excess) < 5e-4 ? 0.0 : 100 * a.excess;  // no "-0.0 %" from round-off
  out += " | " + (made ? number(percent, "%.1f %%") : std::string()) + " | " + number(a.seconds, "%.2f");
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tries every model of a folder (Debian's assimp-testmodels) as a moving body of a gjkx scene, "
               "decomposed and as its hull, and writes the Markdown table of docs 06.",
               "gjkx_mesh_table"};
  std::string folder = "/usr/share/assimp/models", out;
  double budget = 2, limit = 45;
  app.add_option("--models", folder, "the folder of models, searched with its subfolders")->capture_default_str();
  app.add_option("--out", out, "the Markdown file to write")->required();
  app.add_option("--budget", budget, "seconds each decomposition may take (gjkx_simulate's --decompose-budget)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--limit", limit, "seconds a model may take in all before its worker is stopped")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  if (fs::is_directory(folder)) folder = fs::canonical(folder).string();  // the messages' paths are cut after it
  if (!fs::is_directory(folder)) {
    std::cerr << "gjkx_mesh_table: " << folder
              << " is not a folder (Debian's assimp-testmodels installs /usr/share/assimp/models; cmake/install-deps.sh)\n";
    return 1;
  }
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), folder).string());
  std::sort(files.begin(), files.end());

  std::vector<Row> rows;
  int unread = 0;
  const auto start = std::chrono::steady_clock::now();
  const bool bar = isatty(fileno(stderr));
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string& relative = files[k];
    std::string answer;
    const gjkx::WorkerEnd end = gjkx::runForked(
        [&](int fd) {
          const std::string text = measure(folder, relative, budget);
          return gjkx::writeAll(fd, text.data(), text.size()) ? 0 : 3;
        },
        limit, [&](std::string_view chunk) { answer.append(chunk); });
    Row row;
    row.path = relative;
    std::istringstream in(answer);
    std::string kind;
    std::getline(in, kind);
    if (end.exited && end.exitCode == 0 && kind == "unread") {
      ++unread;
      continue;
    }
    if (end.exited && end.exitCode == 0 && kind == "read" && (in >> row.triangles >> row.vertices >> row.closed) &&
        (in.ignore(1, '\n'), get(in, row.decompose)) && get(in, row.hull)) {
      rows.push_back(row);
    } else {  // a crash or a hang of the worker (Assimp's test models include its bug reports)
      row.decompose.result = row.hull.result =
          end.timedOut ? "no answer within " + number(limit, "%g") + " s (stopped)"
                       : "the worker died (" + std::string(end.signal ? strsignal(end.signal) : "exit status " + std::to_string(end.exitCode)) + ")";
      row.decompose.result = "refused: " + row.decompose.result;
      row.hull.result = row.decompose.result;
      row.decompose.seconds = row.hull.seconds = end.seconds;
      rows.push_back(row);
    }
    if (bar)
      chapter::progressBar(int(40 * (k + 1) / files.size()), "model " + std::to_string(k + 1) + "/" + std::to_string(files.size()),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  if (bar) std::fprintf(stderr, "\n");

  int decomposed = 0, fellBack = 0, refused = 0, hulls = 0;
  for (const Row& r : rows) {
    decomposed += r.decompose.result == "decomposed";
    fellBack += r.decompose.result == "hull after the budget";
    refused += r.decompose.result.rfind("refused", 0) == 0;
    hulls += r.hull.result == "hull";
  }
  std::ofstream table(out);
  table << "Every model of Debian's `assimp-testmodels` (" << folder << "): the " << rows.size()
        << " files that Assimp reads, or that gjkx refuses with a message of its own before or after Assimp (an empty "
        << "file, a face index out of range, no triangles); the other " << unread
        << " files there are images, materials, or files Assimp could not read. Each was "
        << "made a moving body by gjkx_simulate's path (gjkx::buildBodies, no mesh cache) with a decomposition "
        << "budget of " << number(budget, "%g") << " s (the scene's default is 30 s): as `{\"mesh\": path}` "
        << "(decomposed: " << decomposed << "; its hull after the budget: " << fellBack << "; refused: " << refused
        << ") and as `{\"mesh\": path, \"collision\": \"hull\"}` (its hull: " << hulls << "). Pieces: the convex pieces "
        << "(fewest–most hull vertices per piece); volume excess: the pieces' volumes over the mesh's, minus one (for an "
        << "open mesh, the mesh's volume is that of the cones from its vertices' centroid); seconds: building the body. "
        << "Written by `gjkx_mesh_table --out figures/data/assimp-meshes.md --budget " << number(budget, "%g")
        << "` (the target `figures`), never by hand.\n\n";
  table << "| model | triangles | closed | `decompose` | pieces | volume excess | s | `hull` | hull vertices | volume excess | s |\n"
        << "| --- | ---: | --- | --- | ---: | ---: | ---: | --- | ---: | ---: | ---: |\n";
  for (const Row& r : rows)
    table << "| " << r.path << " | " << r.triangles << " | " << (r.closed ? "yes" : "no") << " | "
          << cells(r.decompose, true) << " | " << cells(r.hull, false) << " |\n";
  if (!table) {
    std::cerr << "gjkx_mesh_table: cannot write " << out << "\n";
    return 1;
  }
  std::printf("gjkx_mesh_table: %zu models (%d decomposed, %d hull after the budget, %d refused; %d as hulls), %d files "
              "unread, %.0f s: %s\n",
              rows.size(), decomposed, fellBack, refused, hulls, unread,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), out.c_str());
  return 0;
}
