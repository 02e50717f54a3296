// Run time against error (issue 3): every integrator of rbsim::integratorNames() at five time
// steps on three cases with exact solutions (bench/accuracy/cases.h), run through rbsim::World.
// Writes one CSV row per (case, integrator, dt) and prints a summary at dt = 1/60 s and the most
// accurate integrator per cost bracket. bench/run_accuracy_sweep.sh adds the gnuplot figures.
//
// Usage: accuracy_sweep [CSV_PATH] [--timing-seconds S]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "accuracy/cases.h"
#include "accuracy/measure.h"
#include "rbsim/integrate/integrator.h"

namespace {

using namespace rbsim;
using namespace rbsim::accuracy;

constexpr double kDuration = 20.0;        // simulated time per run [s]
constexpr double kSampleInterval = 0.05;  // exact solution sampled at least this often [s]
// A short horizon as well as the full one: over 20 s every first-order method loses the box's
// orientation entirely (error ~ pi, the curves pile up at the top); over the first 2 s, before
// the first flip (at ~2.2 s), their errors are still below pi and their order shows (the
// horizon of tests/engine/reference/convergence_test.cpp).
constexpr double kEarlyHorizon = 2.0;     // [s]
constexpr double kMinTimingSeconds = 0.2; // wall time accumulated per timing cell [s] (default)
constexpr int kMinTimingRepeats = 3;      // runs per timing cell at least, for a median
constexpr int kStepRates[] = {30, 60, 120, 240, 1000};  // 1 / dt [1/s]
constexpr int kSummaryRate = 60;          // the summary table's 1 / dt [1/s]
// Budgets of wall time per simulated second for "best integrator per cost" [us per s]: a 1-2-5
// ladder spanning the cheapest cell (euler-quat at 1/30 s, ~4 us per simulated second on the
// development machine) to the dearest (dlm at 1/1000 s, ~300 us, more on a loaded machine).
constexpr double kBudgets[] = {5, 10, 20, 50, 100, 200, 500, 1000};
// The box's quoted omega period and TorqueFreeExact's must agree to this relative accuracy.
constexpr double kPeriodTolerance = 1e-9;  // [1]
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Beyond a quarter turn of error the simulated body points nowhere near the true one: a "best"
// integrator above it is only the least bad, and the summary says so.
constexpr double kLostAngle = 1.5707963267948966;  // pi / 2 [rad]

struct Cell {
  const ReferenceCase* refCase;
  std::string integrator;
  int stepRate;  // 1 / dt [1/s]
  Accuracy accuracy;
  Timing timing;

  double dt() const { return 1.0 / stepRate; }
  // Costs are the fastest of the repeats: other jobs on a shared machine only ever add time.
  double nsPerStep() const { return timing.minRunSeconds / static_cast<double>(timing.steps) * 1e9; }
  double msPerRun() const { return timing.minRunSeconds * 1e3; }
  double usPerSimSecond() const { return timing.minRunSeconds / kDuration * 1e6; }
};

// printf's "%e" of a NaN may print "-nan"; the CSV and the plot script expect exactly "nan".
std::string num(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6e", value);
  return buffer;
}

void writeCsv(const std::string& path, const std::vector<Cell>& cells) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) {
    std::fprintf(stderr, "accuracy_sweep: cannot write %s\n", path.c_str());
    std::exit(1);
  }
  std::fprintf(out,
               "case,integrator,steps_per_s,dt_s,sim_time_s,steps,timing_repeats,wall_ns_per_step,"
               "wall_ns_per_step_median,wall_ms_per_run,orient_err_max_rad,orient_err_final_rad,early_horizon_s,"
               "orient_err_max_early_rad,"
               "energy_drift_max_rel,energy_drift_final_rel,momentum_drift_max_rel,momentum_drift_final_rel,"
               "position_err_max_m,position_err_final_m,flip_status,flip_count,flip_count_exact,"
               "last_flip_s,flip_half_period_s,flip_half_period_exact_s,flip_period_err_rel,diverged\n");
  for (const Cell& c : cells) {
    const Accuracy& a = c.accuracy;
    const ReferenceCase& rc = *c.refCase;
    const double steps = static_cast<double>(c.timing.steps);
    std::fprintf(out, "%s,%s,%d,%s,%s,%ld,%d,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%d,%d,%s,%s,%s,%s,%d\n",
                 rc.name.c_str(), c.integrator.c_str(), c.stepRate, num(c.dt()).c_str(), num(kDuration).c_str(),
                 c.timing.steps, c.timing.repeats, num(c.nsPerStep()).c_str(),
                 num(c.timing.medianRunSeconds / steps * 1e9).c_str(), num(c.msPerRun()).c_str(),
                 num(a.orientErrMax).c_str(), num(a.orientErrFinal).c_str(), num(kEarlyHorizon).c_str(),
                 num(a.orientErrMaxEarly).c_str(), num(a.energyDriftMax).c_str(),
                 num(a.energyDriftFinal).c_str(), num(a.momentumDriftMax).c_str(), num(a.momentumDriftFinal).c_str(),
                 num(a.positionErrMax).c_str(), num(a.positionErrFinal).c_str(), flipStatusName(a.flipStatus),
                 a.flipCount, rc.flips ? rc.exactFlipCount : 0, num(a.lastFlip).c_str(), num(a.flipHalfPeriod).c_str(),
                 num(rc.flips ? rc.exactHalfPeriod : kNaN).c_str(), num(a.flipPeriodErr).c_str(), a.diverged ? 1 : 0);
  }
  std::fclose(out);
}

// The flip column of the summary: the relative period error, or why there is none.
std::string flipText(const Cell& c) {
  const Accuracy& a = c.accuracy;
  char buffer[64];
  switch (a.flipStatus) {
    case FlipStatus::NotApplicable: return "-";
    case FlipStatus::NoFlip:
      if (a.flipCount == 0) return "NO FLIP";
      std::snprintf(buffer, sizeof buffer, "NO FLIP (%d, the last at %.1f s)", a.flipCount, a.lastFlip);
      return buffer;
    case FlipStatus::WrongCount:
      std::snprintf(buffer, sizeof buffer, "%.2e (%d flips, exact %d)", a.flipPeriodErr, a.flipCount,
                    c.refCase->exactFlipCount);
      return buffer;
    case FlipStatus::Flipping:
      std::snprintf(buffer, sizeof buffer, "%.2e", a.flipPeriodErr);
      return buffer;
  }
  return "?";
}

const Cell* find(const std::vector<Cell>& cells, const std::string& caseName, const std::string& integrator, int rate) {
  for (const Cell& c : cells) {
    if (c.refCase->name == caseName && c.integrator == integrator && c.stepRate == rate) return &c;
  }
  return nullptr;
}

void printSummary(const std::vector<ReferenceCase>& cases, const std::vector<std::string>& names,
                  const std::vector<Cell>& cells) {
  const std::string& box = cases.front().name;
  std::printf("\nTorque-free box at dt = 1/%d s over %.0f s (%s; exact flip half period %.6f s, %d flips)\n",
              kSummaryRate, kDuration, cases.front().description.c_str(), cases.front().exactHalfPeriod,
              cases.front().exactFlipCount);
  char early[32];
  std::snprintf(early, sizeof early, "first %.0f s rad", kEarlyHorizon);
  std::printf("%-17s %12s %12s %14s %14s %14s %14s  %s\n", "integrator", "wall ns/step", "wall ms/run",
              "orient max rad", early, "|E/E0-1| max", "||L|/L0-1| max", "flip-period err");
  for (const std::string& name : names) {
    const Cell* c = find(cells, box, name, kSummaryRate);
    if (!c) continue;
    std::printf("%-17s %12.0f %12.3f %14.3e %14.3e %14.3e %14.3e  %s%s\n", name.c_str(), c->nsPerStep(),
                c->msPerRun(), c->accuracy.orientErrMax, c->accuracy.orientErrMaxEarly,
                c->accuracy.energyDriftMax,
                c->accuracy.momentumDriftMax, flipText(*c).c_str(), c->accuracy.diverged ? "  DIVERGED" : "");
  }

  std::printf("\nOther cases at dt = 1/%d s (max over %.0f s)\n", kSummaryRate, kDuration);
  std::printf("%-17s %-15s %14s %14s %14s\n", "integrator", "case", "orient max rad", "|E/E0-1| max", "pos err max m");
  for (std::size_t k = 1; k < cases.size(); ++k) {
    for (const std::string& name : names) {
      const Cell* c = find(cells, cases[k].name, name, kSummaryRate);
      if (!c) continue;
      std::printf("%-17s %-15s %14.3e %14.3e %14.3e%s\n", name.c_str(), cases[k].name.c_str(), c->accuracy.orientErrMax,
                  c->accuracy.energyDriftMax, c->accuracy.positionErrMax, c->accuracy.diverged ? "  DIVERGED" : "");
    }
  }

  // Same dt, same number of steps: the most accurate integrator per step size, for each case.
  std::printf("\nBest integrator per dt (smallest max orientation error [rad])\n%-8s", "dt [s]");
  for (const ReferenceCase& rc : cases) std::printf("  %-32s", rc.name.c_str());
  std::printf("\n");
  for (int rate : kStepRates) {
    std::printf("1/%-6d", rate);
    for (const ReferenceCase& rc : cases) {
      const Cell* best = nullptr;
      for (const std::string& name : names) {
        const Cell* c = find(cells, rc.name, name, rate);
        if (c && !c->accuracy.diverged && (!best || c->accuracy.orientErrMax < best->accuracy.orientErrMax)) best = c;
      }
      char text[64];
      std::snprintf(text, sizeof text, "%s %.2e%s", best ? best->integrator.c_str() : "-",
                    best ? best->accuracy.orientErrMax : kNaN,
                    best && best->accuracy.orientErrMax > kLostAngle ? " (lost)" : "");
      std::printf("  %-32s", text);
    }
    std::printf("\n");
  }

  // Same wall-clock budget: any (integrator, dt) whose cost per simulated second fits.
  std::printf("\nBest (integrator, dt) per wall-time budget, torque-free box (smallest max orientation error)\n");
  std::printf("%-22s %-17s %-8s %14s %16s\n", "budget [us / sim s]", "integrator", "dt [s]", "orient max rad",
              "cost [us/sim s]");
  for (double budget : kBudgets) {
    const Cell* best = nullptr;
    for (const Cell& c : cells) {
      if (c.refCase->name != box || c.accuracy.diverged || !(c.usPerSimSecond() <= budget)) continue;
      if (!best || c.accuracy.orientErrMax < best->accuracy.orientErrMax) best = &c;
    }
    if (!best) {
      std::printf("%-22.0f %-17s\n", budget, "(nothing this cheap)");
      continue;
    }
    char dtText[16];
    std::snprintf(dtText, sizeof dtText, "1/%d", best->stepRate);
    std::printf("%-22.0f %-17s %-8s %14.3e %16.1f%s\n", budget, best->integrator.c_str(), dtText,
                best->accuracy.orientErrMax, best->usPerSimSecond(),
                best->accuracy.orientErrMax > kLostAngle ? "  (orientation lost)" : "");
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string csvPath = "accuracy.csv";
  double timingSeconds = kMinTimingSeconds;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--timing-seconds") == 0 && i + 1 < argc) {
      timingSeconds = std::atof(argv[++i]);
    } else if (argv[i][0] == '-') {
      std::fprintf(stderr, "usage: %s [CSV_PATH] [--timing-seconds S]\n", argv[0]);
      return 2;
    } else {
      csvPath = argv[i];
    }
  }

  const std::vector<ReferenceCase> cases = referenceCases(kDuration);
  const double period = 2.0 * cases.front().exactHalfPeriod;
  if (std::abs(period / kBoxOmegaPeriod - 1.0) > kPeriodTolerance) {
    std::fprintf(stderr, "accuracy_sweep: the box's exact period %.12f s differs from the quoted %.12f s\n", period,
                 kBoxOmegaPeriod);
    return 1;
  }

  const std::vector<std::string> names = integratorNames();
  std::vector<Cell> cells;
  for (const ReferenceCase& rc : cases) {
    for (const std::string& name : names) {
      Integrator integrator;
      if (!parseIntegrator(name, integrator)) {
        std::fprintf(stderr, "accuracy_sweep: integratorNames() lists '%s', which parseIntegrator rejects\n", name.c_str());
        return 1;
      }
      for (int rate : kStepRates) {
        Cell cell{&rc, name, rate, {}, {}};
        cell.accuracy = measureAccuracy(rc, integrator, cell.dt(), kDuration, kSampleInterval, kEarlyHorizon);
        cell.timing = measureTiming(rc, integrator, cell.dt(), kDuration, timingSeconds, kMinTimingRepeats);
        std::fprintf(stderr, "%-16s %-17s dt = 1/%-4d %8.0f ns/step  orient max %.3e rad%s\n", rc.name.c_str(),
                     name.c_str(), rate, cell.nsPerStep(), cell.accuracy.orientErrMax,
                     cell.accuracy.diverged ? "  DIVERGED" : "");
        cells.push_back(cell);
      }
    }
  }

  writeCsv(csvPath, cells);
  std::printf("Wrote %zu rows to %s\n", cells.size(), csvPath.c_str());
  printSummary(cases, names, cells);
  return 0;
}
