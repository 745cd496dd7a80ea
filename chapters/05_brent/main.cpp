// Chapter 05: the maximum supporting distance over time (§4) and Brent's method (§5).
//
// §4: "If we represent the maximum supporting distance between P(t) and Q(t) as a
// continuous scalar function of time, we can identify collisions by checking whether or
// not this function drops below zero, and then determine their exact TOI with a root
// solver." §5 approximates that function by "the maximum value of SD(P(t_1), Q(t_1), s_i)
// among those we calculated before the GJK query halted" and solves it with Brent's
// method, "a root solver that cleverly combines bisection, the secant method, and inverse
// quadratic interpolation". Three figures, drawn from the library's own runs
// (timeOfImpact with a ToiTrace, findRoot), for polygons in the plane z = 0 over [0, 1]:
//   brent-time-of-impact.png  a box turning as it moves onto a fixed polygon: the true
//       maximum SD, the approximation of every complete extrusion test, Brent's iterates
//       t_x, the restarts and the time of impact, and the bodies at those times
//       (time_of_impact_figure.hpp; the box's motion, its size and the tolerance are options);
//   brent-photo-finish.png    a bar turning as it passes the corner of a block
//       (photo_finish_figure.hpp);
//   brent-root-finder.png     Brent's method alone, on his own example x^3 - 2x - 5
//       (root_finder_figure.hpp).
// --trace prints each run's trace as tables (toi_trace.hpp; docs/traces.md).
#include "../chapter.hpp"
#include "photo_finish_figure.hpp"
#include "root_finder_figure.hpp"
#include "time_of_impact_figure.hpp"
#include "toi_trace.hpp"

#include <gjkx/root_solver/brent_method.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace brent_figures;

namespace {

auto polygon(const std::vector<V>& corners) { return Polytope<double>::polygon(corners); }
const Motion<double> atRest = Motion<double>::fixed(Pose<double>::identity());

// The box Q of the time-of-impact figure, w x h, centred on its origin.
Polytope<double> box(double w, double h) {
  return polygon({V(-w / 2, -h / 2, 0), V(w / 2, -h / 2, 0), V(w / 2, h / 2, 0), V(-w / 2, h / 2, 0)});
}

// Brent's method on f over [1, 3] as a table: each iterate, its kind and the bracket after it.
template <typename F>
void printRootTrace(const RootResult<double>& root, F&& f) {
  const auto brackets = bracketsOf(root, 1.0, 3.0, f);
  chapter::TraceTable table{"brent-root-finder: findRoot(x^3 - 2x - 5, 1, 3, 1e-10), Brent's method alone (§5)",
                            {"#", "x", "f(x)", "kind", "a", "b"}, {}};
  for (std::size_t k = 0; k < root.iterates.size(); ++k)
    table.rows.push_back({std::to_string(k + 1), format("%.12f", root.iterates[k].x),
                          format("%+.3e", root.iterates[k].fx), toString(root.iterates[k].kind),
                          format("%.12f", brackets[k + 1].first), format("%.12f", brackets[k + 1].second)});
  table.print();
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", solver = "gjkx", start = "6,0,0.3", velocity = "-5,-1", size = "2,1.2";
  double spin = -0.8, tolerance = kTol;
  bool trace = false;
  CLI::App app{"Draws chapter 05's figures in DIR: the time of impact, the photo finish and Brent's method. "
               "The --q-* options and --tolerance change the time of impact's query (docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, trace);
  app.add_option("--solver", solver,
                 "the time-of-impact solver of the figures: this project's (gjkx) or §5 exactly as the paper "
                 "wrote it (paper: ToiSettings::paper())")
      ->check(CLI::IsMember({"paper", "gjkx"}))
      ->capture_default_str();
  auto* startOption = chapter::addPoseOption(app, "--q-start", start, "the box Q's pose at t_0: its centre and angle (radians)");
  auto* velocityOption = app.add_option("--q-velocity", velocity, "Q's velocity over [0, 1]")
                             ->check(chapter::numbers(2, 2, "VX,VY"))
                             ->capture_default_str();
  auto* spinOption =
      app.add_option("--q-spin", spin, "Q's angular velocity about z (radians over [0, 1])")
          ->check(CLI::Range(-1000.0, 1000.0))
          ->capture_default_str();
  auto* sizeOption =
      app.add_option("--q-size", size, "Q's width and height")->check(chapter::numbers(2, 2, "W,H"))->capture_default_str();
  auto* toleranceOption = app.add_option("--tolerance", tolerance, "the collision tolerance (§2.3) of both solver runs")
                              ->check(CLI::PositiveNumber)
                              ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  const std::vector<double> wh = chapter::numberList(size), v = chapter::numberList(velocity);
  if (wh[0] <= 0 || wh[1] <= 0) chapter::badOption(app, "--q-size", "W and H must be positive, got '" + size + "'");
  std::filesystem::create_directories(out);
  const bool query = startOption->count() + velocityOption->count() + spinOption->count() + sizeOption->count() +
                         toleranceOption->count() > 0;
  ToiSettings<double> settings = ToiSettings<double>::of(solver == "paper" ? ToiSolverMode::Paper : ToiSolverMode::Gjkx);
  settings.collisionTolerance = tolerance;

  // ---- Figure 1: a time of impact. Q, a 2 x 1.2 box, moves by (-5, -1) and turns by -0.8
  // rad over [0, 1] onto the fixed P, so SD along a fixed direction is not linear in t.
  const Body P1 = moving(polygon({V(0, -1.5, 0), V(2, 0.5, 0), V(0.3, 1.8, 0), V(-1.2, 0.4, 0)}), atRest);
  const Body Q1 = moving(box(wh[0], wh[1]),
                         Motion<double>::screw(chapter::planarPose(chapter::numberList(start)), V(v[0], v[1], 0),
                                               V(0, 0, spin)));
  std::printf("figure 1, time of impact: ");
  const Run hit = solve(P1, Q1, settings);
  if (!query && (hit.result.status != ToiStatus::Hit || hit.result.restarts < 1)) {
    std::fprintf(stderr, "figure 1: expected a hit after a restart\n");
    return 1;
  }
  if (trace) printToiTrace("brent-time-of-impact", hit.trace, hit.result);
  timeOfImpactFigure(out, P1, Q1, hit, query ? windowsOf(P1, Q1, hit) : ToiWindows{});

  // ---- Figure 2: a photo finish. A 3.2 x 0.6 bar moves by (-8, 1) over the corner of the
  // block P and turns by -2 rad: no single direction separates them at both t_0 and t_1.
  const Body P2b = moving(polygon({V(-1.5, -1.5, 0), V(1.5, -1.5, 0), V(1.5, 1, 0), V(0.5, 1.5, 0), V(-1.5, 1.5, 0)}),
                          atRest);
  const Body Q2 = moving(polygon({V(-1.6, -0.3, 0), V(1.6, -0.3, 0), V(1.6, 0.3, 0), V(-1.6, 0.3, 0)}),
                         Motion<double>::screw(Pose<double>::fromAxisAngle(V::UnitZ(), 1.0, V(4, 2.3, 0)), V(-8, 1, 0),
                                               V(0, 0, -2)));
  std::printf("figure 2, photo finish: ");
  const Run finish = solve(P2b, Q2, settings);
  if (!query && finish.result.status != ToiStatus::PhotoFinish) {
    std::fprintf(stderr, "figure 2: expected a photo finish\n");
    return 1;
  }
  if (trace) printToiTrace("brent-photo-finish", finish.trace, finish.result);
  photoFinishFigure(out, P2b, Q2, finish);

  // ---- Figure 3: Brent's method alone, on his example x^3 - 2x - 5 over [1, 3].
  auto f = [](double x) { return x * x * x - 2 * x - 5; };
  const RootResult<double> root = findRoot(f, 1.0, 3.0, 1e-10);
  std::printf("figure 3, root finder: x^3 - 2x - 5 = 0 at x = %.12f (f = %.2e) after %d iterations, %s\n", root.root,
              root.fRoot, root.iterations, root.status == RootStatus::Converged ? "converged" : "iteration cap");
  if (trace) printRootTrace(root, f);
  rootFinderFigure(out, root, f);
  return 0;
}
