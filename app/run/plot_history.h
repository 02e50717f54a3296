#pragma once
// The time plots of a phase (a scene's view.plots, the --plot flag): per plot and per world the
// samples of the last view.plotSeconds, taken once per frame, for the overlay to draw (PhET's
// energy graphs; issue 24). A compared phase plots one line per world, named by its caption.
#include <deque>
#include <string>
#include <vector>

#include "render/frame_data.h"
#include "run/phase.h"
#include "rbsim/world/free_flight_error.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// A quantity of kPlotQuantities (scene.h) now, of the whole world or of body `selected` alone:
// "ke" the kinetic energy, "pe" gravity's potential energy -m g.x, "E" their sum [J]; "|P|" the
// length of the linear momentum [kg m/s]; "|L|" of the angular momentum, about the origin for
// the world (sum of x x P + L) and about its centre of mass for one body [kg m^2/s]; "contacts"
// the contact points of the last step (of the body's contacts alone); "error" the selected
// body's angle from the exact torque-free motion [rad], NaN while it is not compared (asleep,
// torqued, or `freeFlight` null).
double plotQuantity(const std::string& name, const World& world, bool selectedOnly, std::size_t selected,
                    const FreeFlightError* freeFlight);
// Its unit and a title, e.g. {"J", "E, kinetic + gravity"}.
std::pair<std::string, std::string> plotUnitAndTitle(const std::string& name, bool selectedOnly);

class TimePlots {
 public:
  explicit TimePlots(const Phase& phase);  // the phase's first view decides, as for the camera
  bool empty() const { return names_.empty(); }
  // Takes one sample of every plot from every world at its own time; drops samples older than
  // the window. `freeFlight[k]` follows world k's selected body (null: no error plot values).
  void sample(const std::vector<World>& worlds, const std::vector<FreeFlightError>* freeFlight);
  // The same for world k alone (window mode has one World, not a vector of them).
  void sample(const World& world, const FreeFlightError* freeFlight, std::size_t k = 0);
  std::vector<render::OverlayPlot> plots() const { return plotsAt(now_); }
  // The plots as they were at time t: the window ending at t (the replay window scrubs with this;
  // it keeps every sample, see keepHistory).
  std::vector<render::OverlayPlot> plotsAt(double t) const;
  // Keep samples older than the window too, so plotsAt can go back to any time.
  void keepHistory() { keepHistory_ = true; }

 private:
  struct Series {
    std::deque<float> t, y;
  };
  std::vector<std::string> names_;
  bool selectedOnly_ = false;
  double seconds_ = 10.0;
  std::vector<std::size_t> selected_;  // per world
  std::vector<std::string> legend_;    // per world
  std::string bodyName_;               // of the selected body, for the titles
  std::vector<std::vector<Series>> series_;  // [plot][world]
  double now_ = 0.0;
  bool keepHistory_ = false;
};

}  // namespace rbsim::app
