#pragma once
// Analytic references of a case (`analysis: {name: {params}}` in the case file). An analysis
// watches the run at output times and adds its figures to metrics.json at the end; its
// reference is computed from the case's own values, so `--set` changes both. A flow that is
// known analytically may also provide the initial state (`initial: {name: {params}}`).
// A new analysis is one new file plus one line in registry.cpp.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "curvsph/core/error.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/eos.hpp"

namespace curvsph {

template <int D>
class Analysis {
 public:
  virtual ~Analysis() = default;
  // Called at t = 0 and at every output time.
  virtual void observe(double /*t*/, const Particles<D>& /*P*/) {}
  // Called when the run goes unstable at time t (the last completed step). An analysis whose
  // figure is the time of such an event (Vela Vela eq. 37) returns true: the run then ends
  // there normally, with metrics (`unstable: 1`), instead of exit code 3.
  virtual bool absorb_instability(double /*t*/, const Particles<D>& /*P*/,
                                  const InstabilityError& /*e*/) {
    return false;
  }
  // What observe() accumulated since t = 0, for `run --restart` (the restart state,
  // solver/restart_state.hpp), so that a restarted run's figures measure from the original
  // t = 0; and back (a state of the wrong shape throws nlohmann::json::exception). JSON
  // doubles round-trip exactly. The default: nothing is kept between observations.
  virtual nlohmann::json save_state() const { return nullptr; }
  virtual void load_state(const nlohmann::json& /*state*/) {}
  // Adds the analysis' figures to metrics; may write its curves (CSV) into out_dir when
  // that is not empty.
  virtual void finish(double t, const Particles<D>& P, nlohmann::json& metrics,
                      const std::filesystem::path& out_dir) = 0;
};

template <int D>
std::unique_ptr<Analysis<D>> make_analysis(const std::string& name, const YAML::Node& params,
                                           const Case& c);

// Sets velocity, pressure and density of every particle from a named initial flow field.
template <int D>
void apply_initial_field(const Case& c, const Eos& eos, const std::vector<Real>& rho0,
                         Particles<D>& P);

}  // namespace curvsph
