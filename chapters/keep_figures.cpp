// gjkx_keep_figures NEW KEPT: brings the figures the chapters just drew in NEW into the
// kept folder KEPT (figures/), rewriting a kept PNG only when the new one differs beyond
// the figure tests' tolerance (kept::kTolerance, kept_figures.hpp), and any other file
// (the data of a plot) only when its bytes differ. So regenerating the figures on another
// machine, whose rasteriser may round the last bit of an edge otherwise, leaves figures/
// (and git status) untouched, and a figure that really changed is rewritten.
#include "command_line.hpp"
#include "kept_figures.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;

namespace {

std::string bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

int main(int argc, char** argv) {
  std::string fresh, kept;
  CLI::App app{"Copies the figures just drawn into the kept folder, each only if it differs beyond the figure tests' tolerance."};
  app.add_option("new", fresh, "the folder the chapters drew into")->required()->check(CLI::ExistingDirectory);
  app.add_option("kept", kept, "the kept folder (figures/)")->required();
  chapter::parseOrExit(app, argc, argv);
  int rewritten = 0, unchanged = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fresh)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), fresh), target = fs::path(kept) / relative;
    bool same = fs::exists(target);
    std::string how = "new";
    if (same && entry.path().extension() == ".png") {
      const kept::Diff diff = kept::compare(kept::readPng(target.string()), kept::readPng(entry.path().string()));
      same = diff.same();
      char percent[64];
      std::snprintf(percent, sizeof percent, "%.2f%% of the pixels differ", diff.differingFraction * 100);
      how = diff.sameSize ? percent : "another size";
    } else if (same) {
      same = bytesOf(target) == bytesOf(entry.path());
      how = "other bytes";
    }
    if (same) {
      ++unchanged;
      continue;
    }
    fs::create_directories(target.parent_path());
    fs::copy_file(entry.path(), target, fs::copy_options::overwrite_existing);
    std::printf("rewrote %s (%s)\n", target.string().c_str(), how.c_str());
    ++rewritten;
  }
  std::printf("gjkx_keep_figures: %d rewritten, %d the same within tolerance\n", rewritten, unchanged);
  return 0;
}
