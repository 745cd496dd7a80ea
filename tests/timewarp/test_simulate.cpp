// gjkx_simulate as a user runs it: the example scenes of chapter 07 run to the end and
// write the documented CSV columns and SUMMARY keys (docs/07_timewarp.md), nothing
// tunnels; a bad scene is refused before the run, naming the body and the field.
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <gjkx/timewarp/frame.hpp>
#include <gjkx/timewarp/scene.hpp>


#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <map>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using Result = test::ProgramResult;

// Runs gjkx_simulate (its path passed in by tests/CMakeLists.txt) with `arguments`.
Result simulate(const std::string& arguments) { return test::runProgram(GJKX_SIMULATE, arguments); }

fs::path freshFolder(const std::string& name) { return test::freshFolder("gjkx-simulate", name); }

std::string firstLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

long lineCount(const fs::path& file) {
  std::ifstream in(file);
  long n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

// The key=value pairs of the line of `output` that starts with `tag` and a space (the
// SUMMARY line by default; empty if there is none).
std::map<std::string, std::string> summary(const std::string& output, const std::string& tag = "SUMMARY") {
  std::map<std::string, std::string> keys;
  const std::string start = tag + " ";
  const auto at = output.find(start);
  if (at == std::string::npos) return keys;
  std::stringstream line(output.substr(at + start.size(), output.find('\n', at) - at - start.size()));
  for (std::string item; line >> item;) {
    const auto eq = item.find('=');
    if (eq != std::string::npos) keys[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return keys;
}

}  // namespace

TEST_CASE("gjkx_simulate runs the cradle and writes the documented outputs", "[simulate]") {
  const fs::path out = freshFolder("cradle");
  const Result r =
      simulate("\"" + std::string(GJKX_SCENES) + "/cradle.json\" --out \"" + out.string() + "\" --quiet --checks");
  INFO(r.output);
  REQUIRE(r.status == 0);
  REQUIRE(fs::exists(out / "checks.csv"));
  CHECK(firstLine(out / "checks.csv") == "frame,time,kind,body,other,depth");
  CHECK(lineCount(out / "checks.csv") == 1);  // nothing found: the header alone
  CHECK(r.output.find("(not checked)") == std::string::npos);
  REQUIRE(fs::exists(out / "frames.csv"));
  REQUIRE(fs::exists(out / "bodies.csv"));
  CHECK(firstLine(out / "frames.csv") ==
        "frame,time,wall_s,collision_checks,collisions,rollbacks,brent_iterations,photo_finishes,max_penetration,"
        "events,microcollisions,bodies_rolled_back,brent_max,complete_tests,solver_caps,tunnelled,integration_s,"
        "bounds_s,collision_detection_s,impulses_s,ordering_s,checks_s,brent_queries,caught,spin_restarts,event_caps,projections,"
        "contact_points,contact_groups,contact_sweeps,energy_rises,sleeping,contacts_s,cpu_s,landings,static_checks,contact_impulses,"
        "cascade_impulses,step_ends,rechecked_after_collisions,rechecked_at_step_ends,"
        "checked_at_interval_starts,intervals");
  CHECK(firstLine(out / "bodies.csv") == "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy");
  const auto keys = summary(r.output);
  for (const char* key : {"frames", "sim_s", "wall_s", "collisions", "rollbacks", "brent_mean", "brent_max",
                          "photo_finish", "max_penetration", "tunnelled"}) {
    INFO("SUMMARY key " << key);
    CHECK(keys.count(key) == 1);
  }
  REQUIRE(keys.count("frames") == 1);
  const long frames = std::stol(keys.at("frames"));
  CHECK(frames == 24);                                     // 1 s at 24 frames per second
  CHECK(lineCount(out / "frames.csv") == 1 + frames);      // a row per frame
  CHECK(lineCount(out / "bodies.csv") == 1 + 5 * frames);  // a row per frame and ball
  CHECK(keys.count("tunnelled") == 1);
  if (keys.count("tunnelled")) CHECK(keys.at("tunnelled") == "0");
  // The momentum runs down the row of five: four collisions, each found late and rolled back.
  if (keys.count("collisions")) CHECK(std::stol(keys.at("collisions")) == 4);
  // summary.txt's WORK line ends with the process's peak resident memory: at least the few
  // megabytes any process takes, far below what five balls could need.
  std::ifstream file(out / "summary.txt");
  std::string text;
  for (std::string line; std::getline(file, line);) text += line + "\n";
  const auto work = summary(text, "WORK");
  REQUIRE(work.count("peak_memory_mb") == 1);
  CHECK(text.find(" peak_memory_mb=") > text.find(" event_caps="));  // the last key, added at the end
  CHECK(std::stod(work.at("peak_memory_mb")) > 1.0);
  CHECK(std::stod(work.at("peak_memory_mb")) < 4096.0);
  fs::remove_all(out);
}

TEST_CASE("gjkx_simulate without --checks says so: -1 and (not checked), no checks.csv", "[simulate]") {
  const fs::path out = freshFolder("unchecked");
  const Result r = simulate("\"" + std::string(GJKX_SCENES) + "/ball_drop.json\" --out \"" + out.string() + "\" --quiet");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto keys = summary(r.output);
  REQUIRE(keys.count("tunnelled") == 1);
  CHECK(keys.at("tunnelled") == "-1");
  CHECK(keys.at("max_penetration") == "-1");
  CHECK(r.output.find("(not checked)") != std::string::npos);
  CHECK(!fs::exists(out / "checks.csv"));
  fs::remove_all(out);
}

TEST_CASE("gjkx_simulate runs the other example scenes without tunnelling", "[simulate]") {
  // The tori: four closed meshes dropped on a static one, whose prisms once made a node
  // hull Qhull could not build right (convex_hull.cpp, near duplicates).
  for (const std::string& scene : {std::string(GJKX_SCENES) + "/ball_drop.json", std::string(GJKX_SCENES) + "/dominoes.json",
                                  std::string(GJKX_TORSO_SCENES) + "/tori.json"}) {
    const fs::path out = freshFolder(fs::path(scene).filename().string());
    const Result r = simulate("\"" + scene + "\" --out \"" + out.string() + "\" --quiet --checks");
    INFO(scene << ": " << r.output);
    CHECK(r.status == 0);
    const auto keys = summary(r.output);
    REQUIRE(keys.count("tunnelled") == 1);
    CHECK(keys.at("tunnelled") == "0");
    fs::remove_all(out);
  }
}

TEST_CASE("gjkx_simulate refuses a scene with an unknown key, naming the body and the field", "[simulate]") {
  const fs::path dir = freshFolder("bad");
  {
    std::ofstream scene(dir / "bad.json");
    scene << R"({ "duration": 1, "bodies": [
      { "name": "floor", "shape": {"box": [1, 1, 0.5]}, "position": [0, 0, -0.5], "static": true },
      { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1], "radius": 0.1 } ] })";
  }
  const Result r = simulate("\"" + (dir / "bad.json").string() + "\" --out \"" + (dir / "out").string() + "\" --quiet");
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(r.output.find("body 'ball'") != std::string::npos);
  CHECK(r.output.find("field 'radius'") != std::string::npos);
  CHECK(r.output.find("SUMMARY") == std::string::npos);  // refused before the run
  CHECK_FALSE(fs::exists(dir / "out" / "frames.csv"));
  fs::remove_all(dir);
}

TEST_CASE("gjkx_simulate refuses a collision tolerance that is not a positive finite length", "[simulate]") {
  for (const std::string value : {"-1", "0", "nan", "inf"}) {
    const Result r = simulate("\"" + std::string(GJKX_SCENES) + "/ball_drop.json\" --tolerance " + value + " --quiet");
    INFO(value << ": " << r.output);
    CHECK(r.status == 2);
    CHECK(r.output.find("--tolerance") != std::string::npos);
    CHECK(r.output.find("SUMMARY") == std::string::npos);
  }
}

TEST_CASE("gjkx_simulate overrides duration and frame rate, and writes the collision log", "[simulate]") {
  const fs::path out = freshFolder("log");
  const Result r = simulate("\"" + std::string(GJKX_SCENES) + "/cradle.json\" --out \"" + out.string() +
                            "\" --quiet --duration 0.5 --frame-rate 48 --log \"" + (out / "log.csv").string() + "\"");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto keys = summary(r.output);
  REQUIRE(keys.count("frames") == 1);
  CHECK(keys.at("frames") == "24");  // 0.5 s at 48 frames per second
  REQUIRE(fs::exists(out / "log.csv"));
  CHECK(firstLine(out / "log.csv") == "time,body,other,piece,other_piece,approach_speed,impulse,microcollision,contact,separation_speed");
  CHECK(lineCount(out / "log.csv") == 1 + std::stol(keys.at("collisions")));  // a row per collision
  fs::remove_all(out);
}

TEST_CASE("gjkx_simulate --tuning sets a constant of the step, says so, and refuses a bad one by name", "[simulate]") {
  const fs::path out = freshFolder("tuning");
  const std::string scene = "\"" + std::string(GJKX_SCENES) + "/cradle.json\" --out \"" + out.string() + "\" --quiet";
  const auto summaryFile = [&] {
    std::ifstream in(out / "summary.txt");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  // A cap of one event per interval: the cradle's collisions reach it, which the WORK line
  // of summary.txt counts (event_caps), where the defaults never do.
  REQUIRE(simulate(scene).status == 0);
  const auto defaults = summary(summaryFile(), "WORK");
  REQUIRE(defaults.count("event_caps") == 1);
  CHECK(defaults.at("event_caps") == "0");
  const Result capped = simulate(scene + " --tuning eventCap=1 --tuning eventCapPerBody=0");
  INFO(capped.output);
  REQUIRE(capped.status == 0);
  CHECK(capped.output.find("reached the event cap") != std::string::npos);
  const std::string text = summaryFile();
  REQUIRE(summary(text, "WORK").count("event_caps") == 1);
  CHECK(std::stol(summary(text, "WORK").at("event_caps")) > 0);
  const auto run = summary(text, "RUN");
  REQUIRE(run.count("tuning.eventCap") == 1);
  CHECK(run.at("tuning.eventCap") == "1");
  CHECK(run.at("tuning.eventCapPerBody") == "0");
  // Refused: an unknown name (the known ones listed), a count that is not whole, no value
  // (the command line: status 2); a number out of the field's range (the world: status 1).
  const Result unknown = simulate(scene + " --tuning contactSettle=0.2");
  CHECK(unknown.status == 2);
  CHECK(unknown.output.find("tuning.contactSettle: no such setting (known: patchDepth,") != std::string::npos);
  const Result fraction = simulate(scene + " --tuning eventCap=1.5");
  CHECK(fraction.status == 2);
  CHECK(fraction.output.find("tuning.eventCap: must be a whole number") != std::string::npos);
  CHECK(simulate(scene + " --tuning eventCap").status == 2);
  const Result range = simulate(scene + " --tuning contactSettled=-1");
  CHECK(range.status == 1);
  CHECK(range.output.find("settings.tuning.contactSettled") != std::string::npos);
  for (const Result* r : {&unknown, &fraction, &range}) CHECK(r->output.find("SUMMARY") == std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("gjkx_simulate refuses a duration whose frames do not fit, naming the file and the field", "[simulate]") {
  const fs::path dir = freshFolder("long");
  fs::create_directories(dir);
  {
    std::ofstream(dir / "long.json") << R"({ "duration": 9e7, "bodies": [ { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1] } ] })";
  }
  const Result r = simulate("\"" + (dir / "long.json").string() + "\" --out \"" + (dir / "out").string() + "\" --quiet");
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(r.output.find("long.json") != std::string::npos);
  CHECK(r.output.find("'duration'") != std::string::npos);
  CHECK(r.output.find("SUMMARY") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("docs 07 names every key of the scene file, every option, every column and every example scene", "[simulate]") {
  // The page is read by people writing their own scenes: a key, an option or a column the
  // code has and the page does not (or an example scene it forgets) fails here.
  std::ifstream in(std::string(GJKX_DOCS) + "/07_timewarp.md");
  REQUIRE(in);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string page = buffer.str();
  const auto named = [&](const std::string& name) { return page.find("`" + name) != std::string::npos; };
  // The columns of frames.csv, from the one table the writer uses.
  for (const gjkx::FrameColumn& column : gjkx::frameColumns()) {
    INFO("frames.csv column " << column.name);
    CHECK(named(column.name));
  }
  // The scene's, a body's, a mesh's and a decomposition's keys, as the parser lists them when it
  // refuses an unknown one; the shapes, as it lists them when it refuses an unknown shape.
  const auto bodyWith = [](const std::string& shape) {
    return R"({ "duration": 1, "bodies": [ { "name": "b", "shape": )" + shape + R"(, "position": [0, 0, 0] } ] })";
  };
  for (const std::string& text : {std::string(R"({"nokey": 1})"), std::string(R"({"mesh": "m.off", "nokey": 1})"),
                                  std::string(R"({"mesh": "m.off", "decomposition": {"nokey": 1}})")}) {
    std::string message;
    try {
      gjkx::parseScene(bodyWith(text), "scene");
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    const auto at = message.find("(known: ");
    REQUIRE(at != std::string::npos);
    const bool shapes = text.find("mesh") == std::string::npos;
    std::stringstream keys(message.substr(at + 8, message.find(')', at) - at - 8));
    for (std::string key; std::getline(keys, key, ',');) {
      key.erase(0, key.find_first_not_of(' '));
      INFO("shape key " << key);
      CHECK((shapes ? page.find("{\"" + key + "\"") != std::string::npos : named(key)));
    }
  }
  for (const std::string& text :
       {std::string(R"({ "duration": 1, "nokey": 1, "bodies": [] })"),
        std::string(R"({ "duration": 1, "bodies": [ { "name": "b", "nokey": 1, "shape": {"sphere": 1}, "position": [0, 0, 0] } ] })")}) {
    std::string message;
    try {
      gjkx::parseScene(text, "scene");
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    const auto at = message.find("(known: ");
    REQUIRE(at != std::string::npos);
    std::stringstream keys(message.substr(at + 8, message.find(')', at) - at - 8));
    for (std::string key; std::getline(keys, key, ',');) {
      key.erase(0, key.find_first_not_of(' '));
      INFO("scene key " << key);
      CHECK(named(key));
    }
  }
  // gjkx_simulate's options, as its --help lists them.
  const Result help = simulate("--help");
  std::stringstream lines(help.output);
  int options = 0;
  for (std::string line; std::getline(lines, line);) {
    const auto dash = line.find("--");
    if (dash == std::string::npos || line.find_first_not_of(' ') != dash || line.compare(dash, 6, "--help") == 0) continue;
    const std::string option = line.substr(dash, line.find_first_of(" ,", dash) - dash);
    ++options;
    INFO("option " << option);
    CHECK(named(option));
  }
  CHECK(options >= 15);
  // The example scenes.
  for (const auto& entry : fs::directory_iterator(GJKX_SCENES)) {
    if (entry.path().extension() != ".json") continue;
    INFO("example scene " << entry.path().filename());
    CHECK(named(entry.path().filename().string()));
  }
}

TEST_CASE("gjkx_simulate --solver paper runs §5 as the paper wrote it, and says so", "[simulate]") {
  const fs::path out = freshFolder("paper_solver");
  const Result r = simulate("\"" + std::string(GJKX_SCENES) + "/ball_drop.json\" --out \"" + out.string() +
                            "\" --quiet --checks --solver paper");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto keys = summary(r.output);
  REQUIRE(keys.count("tunnelled") == 1);
  CHECK(keys.at("tunnelled") == "0");
  std::ifstream file(out / "summary.txt");
  std::string text;
  for (std::string line; std::getline(file, line);) text += line + "\n";
  CHECK(text.find(" solver=paper variant=paper ") != std::string::npos);
  CHECK(text.find(" warm_starts=off coherence=off ") != std::string::npos);
  // The paper's solver runs the paper's extrusion test only.
  const Result refused = simulate("\"" + std::string(GJKX_SCENES) + "/ball_drop.json\" --out \"" + out.string() +
                                  "\" --quiet --solver paper --variant certified");
  CHECK(refused.status == 2);
  CHECK(refused.output.find("--solver paper runs the paper's extrusion test") != std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("gjkx_frame_ratios takes each frame's least time over repeated runs, and refuses runs that differ", "[simulate]") {
  // Two runs of the cradle (deterministic: the same work in each frame), a third of another
  // scene. Each frame's cost over repeats is the least of its processor times (cpu_s).
  const fs::path out = freshFolder("ratios");
  for (const char* run : {"a", "b"})
    REQUIRE(simulate("\"" + std::string(GJKX_SCENES) + "/cradle.json\" --quiet --out \"" + (out / run).string() + "\"").status == 0);
  REQUIRE(simulate("\"" + std::string(GJKX_SCENES) + "/dominoes.json\" --quiet --out \"" + (out / "c").string() + "\"").status == 0);
  const auto csv = [&](const char* run) { return test::readCsv(out / run / "frames.csv"); };
  const auto a = csv("a"), b = csv("b");
  REQUIRE(a.size() == b.size());
  const auto column = [&](const char* name) {
    return std::size_t(std::find(a[0].begin(), a[0].end(), name) - a[0].begin());
  };
  const std::size_t cpu = column("cpu_s"), time = column("time");
  REQUIRE(cpu < a[0].size());
  double slowest = 0, single = 0;
  std::size_t singleAt = 1;  // the row of run a's slowest frame
  for (std::size_t k = 1; k < a.size(); ++k) {
    const double length = std::stod(a[k][time]) - (k > 1 ? std::stod(a[k - 1][time]) : 0.0);
    slowest = std::max(slowest, std::min(std::stod(a[k][cpu]), std::stod(b[k][cpu])) / length);
    if (std::stod(a[k][cpu]) / length > single) {
      single = std::stod(a[k][cpu]) / length;
      singleAt = k;
    }
  }
  const auto ratio = [](const std::string& output, const std::string& key) {
    const auto at = output.find("RATIO " + key + "=");
    REQUIRE(at != std::string::npos);
    return std::stod(output.substr(at + 7 + key.size()));
  };
  const test::ProgramResult both =
      test::runProgram(GJKX_FRAME_RATIOS, "\"both=" + (out / "a").string() + "," + (out / "b").string() + "\"");
  INFO(both.output);
  REQUIRE(both.status == 0);
  CHECK(both.output.find(" runs=2") != std::string::npos);
  CHECK(ratio(both.output, "both_slowest_frame_vs_real_time") == Approx(slowest).epsilon(1e-3));
  CHECK(ratio(both.output, "both_slowest_frame_spread") >= 1.0);
  const test::ProgramResult one = test::runProgram(GJKX_FRAME_RATIOS, "\"one=" + (out / "a").string() + "\"");
  REQUIRE(one.status == 0);
  CHECK(one.output.find("runs=") == std::string::npos);
  CHECK(one.output.find("spread") == std::string::npos);
  CHECK(ratio(one.output, "one_slowest_frame_vs_real_time") == Approx(single).epsilon(1e-3));
  // The slowest frame's events: its number, and each event's cost against real time's.
  {
    INFO(one.output);
    const auto keys = summary(one.output, "SLOWEST one");
    REQUIRE(keys.count("frame") == 1);
    CHECK(keys.at("frame") == std::to_string(singleAt));
    const auto value = [&](const std::string& key) {
      REQUIRE(keys.count(key) == 1);
      return std::stod(keys.at(key));
    };
    const double events = std::stod(a[singleAt][column("events")]);
    const double length = std::stod(a[singleAt][time]) - (singleAt > 1 ? std::stod(a[singleAt - 1][time]) : 0.0);
    REQUIRE(events > 0);
    CHECK(value("events") == events);
    CHECK(value("real_time_per_event_us") == Approx(1e6 * length / events).epsilon(1e-3));
    CHECK(value("cost_per_event_us") == Approx(1e6 * single * length / events).epsilon(1e-3));
    CHECK(value("queries_per_event") == Approx(std::stod(a[singleAt][column("collision_checks")]) / events).epsilon(1e-3));
  }
  // Not the same run: refused, naming the folder.
  const test::ProgramResult mixed =
      test::runProgram(GJKX_FRAME_RATIOS, "\"mixed=" + (out / "a").string() + "," + (out / "c").string() + "\"");
  CHECK(mixed.status == 1);
  CHECK(mixed.output.find((out / "c").string()) != std::string::npos);
  CHECK(mixed.output.find("RATIO") == std::string::npos);
  // A bad command line: exit 2.
  CHECK(test::runProgram(GJKX_FRAME_RATIOS, "nolabel").status == 2);
  fs::remove_all(out);
}
