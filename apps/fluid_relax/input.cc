#include "fluid_relax/input.h"

#include <ddb/groups/sun.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/initial_vorticity.h"
#include "fluid_relax/checkpoint.h"

namespace ddb::fluid {

namespace {

/// Bad input if the first step would overflow: the DDB step squares its dissipative part
/// h|α|‖P₀‖₂‖W₀‖₂/ħ, which past √(largest double) ≈ 1e154 becomes inf and then NaN
/// (measured without this check at N = 8 and 32 with the default h: α = 1e155 ran, and
/// 1e160 made the state NaN at step 0).
/// The check keeps a margin, kMaxDissipativeStep. A huge α below it is valid: the flow
/// relaxes within the step. The flag named is --alpha if α alone makes it too large
/// (with the default α it would pass), else --h if given, else the initial vorticity.
constexpr double kMaxDissipativeStep = 1e150;
void requireRepresentableStep(const CLI::App& cli, const Options& o, const Settings& s) {
  const ZeitlinHamiltonian hamiltonian(s.W0.rows());
  const double scale = SUN::spectralNorm(hamiltonian.streamMatrix(s.W0)) * SUN::spectralNorm(s.W0) /
                       hamiltonian.hbar() * s.h;
  // NaN (0 · inf) fails too.
  const auto fits = [&](double alpha) { return std::abs(alpha) * scale <= kMaxDissipativeStep; };
  if (fits(s.alpha)) return;
  const std::string why = fmt::format(
      "the dissipative step h|alpha||P0|_2|W0|_2/hbar = {:.3g} exceeds {:g} and would "
      "overflow",
      std::abs(s.alpha) * scale, kMaxDissipativeStep);
  if (fits(app::parseNumber("--alpha", Options().alpha, Options().alpha))) {
    app::usageError("--alpha", o.alpha, why);
  }
  if (cli.count("--h") > 0) app::usageError("--h", o.h, why);
  if (!o.init_file.empty()) app::usageError("--init-file", o.init_file, why);
  throw std::logic_error("a generated vorticity overflows: " + why);
}

/// zeitlinDefaultStep (docs/reference/command-lines-and-files.md, "fluid-relax"), which must be a
/// normal double: a huge α or W₀ makes its stiffness limit underflow. The flag named is --alpha if
/// the default α would give a normal step, else the initial vorticity.
double defaultStep(const Options& o, const Settings& s) {
  const auto normal = [](double h) { return h >= std::numeric_limits<double>::min(); };
  double h = zeitlinDefaultStep(s.W0, s.alpha);
  // On a rotating sphere also 0.02/|Ω|: fifty steps per radian of the fastest Rossby–Haurwitz
  // wave, whose angular frequency m·2Ω/(l(l + 1)) is at most |Ω| (l = m = 1).
  if (s.physics.rotation != 0.0) {
    h = std::min(h, kZeitlinContractionRate / std::abs(s.physics.rotation));
  }
  if (normal(h)) return h;
  const std::string why = fmt::format(
      "the default step min({} hbar/|P0|_2, {} hbar/(|alpha||W0|_2^2)) = {:.3g} underflows; "
      "give --h",
      kZeitlinContractionRate, kZeitlinStiffness, h);
  const double default_alpha = app::parseNumber("--alpha", Options().alpha, Options().alpha);
  if (normal(zeitlinDefaultStep(s.W0, default_alpha))) app::usageError("--alpha", o.alpha, why);
  if (!o.init_file.empty()) app::usageError("--init-file", o.init_file, why);
  throw std::logic_error("a generated vorticity underflows the step: " + why);
}

/// --newton's requirements: a tolerance, no time and no step to choose, dissipation.
void readNewton(const CLI::App& cli, const Options& o, Settings& s) {
  for (const char* flag : {"--method", "--h", "--t-end", "--adaptive"}) {
    if (cli.count(flag) > 0) {
      throw app::UsageError(std::string("--newton, ") + flag +
                            ": a Newton search has no method, step size or time (give --steps "
                            "as its cap)");
    }
  }
  if (o.relax.until_steady.empty()) {
    throw app::UsageError("--newton: needs --until-steady TOL, the residual to stop at");
  }
  if (s.alpha == 0) app::usageError("--alpha", o.alpha, "--newton needs alpha != 0 (a direction)");
  s.relax.newton = true;
}

/// --until-steady, --adaptive, --adaptive-tol and --newton into s.relax (the caps are set later).
void readRelaxOptions(const CLI::App& cli, const Options& o, Settings& s) {
  app::readRelaxFlags(o.relax, s.relax);
  if (o.newton) readNewton(cli, o, s);
  // A Newton search looks for a steady state of the Lie–Poisson flow, and the step control's
  // model is the double bracket's energy rate: neither knows the damping.
  if (const auto [flag, text] = exactFlowFlag(o, s);
      !flag.empty() && (o.newton || o.relax.adaptive)) {
    app::usageError(flag, text,
                    std::string(o.newton ? "--newton" : "--adaptive") +
                        " does not take viscosity, drag or forcing (time steps of fixed h do)");
  }
  if (o.relax.adaptive && !findMethod(o.method)->keeps_casimirs) {
    app::usageError("--adaptive", o.method,
                    "needs a method that keeps the Casimirs (the DDB family), not this --method");
  }
  if (o.relax.adaptive && s.alpha == 0) {
    app::usageError("--adaptive", o.alpha, "needs --alpha != 0 (the energy must move)");
  }
}

/// --forcing-band L:D, --forcing-rate (finite, >= 0) and --forcing-seed into s.forcing: both or
/// neither of the band and a rate > 0. The band's degrees are checked against N with W0
/// (requireForcingBand).
void readForcing(const Options& o, Settings& s) {
  s.forcing.rate = app::parseNumber("--forcing-rate", o.forcing_rate, o.forcing_rate);
  if (!(s.forcing.rate >= 0 && std::isfinite(s.forcing.rate))) {
    app::usageError("--forcing-rate", o.forcing_rate, "must be finite and >= 0");
  }
  s.forcing.seed = o.forcing_seed;
  if (o.forcing_band.empty()) {
    if (s.forcing.rate > 0) {
      app::usageError("--forcing-rate", o.forcing_rate,
                      "needs --forcing-band L:D, the forced degrees L-D..L+D");
    }
    return;
  }
  // L or L:D, each a whole number (std::stoi would take "3x" as 3).
  const auto whole = [&](const std::string& text) {
    if (text.empty() || text.size() > 6 ||
        text.find_first_not_of("0123456789") != std::string::npos) {
      app::usageError("--forcing-band", o.forcing_band,
                      "must be L:D (or L), whole numbers with 1 <= L-D and L+D <= N-1");
    }
    return std::stoi(text);
  };
  const std::size_t colon = o.forcing_band.find(':');
  s.forcing.band_centre = whole(o.forcing_band.substr(0, colon));
  s.forcing.band_half_width =
      colon == std::string::npos ? 0 : whole(o.forcing_band.substr(colon + 1));
  if (!(s.forcing.rate > 0)) {
    app::usageError("--forcing-band", o.forcing_band, "needs --forcing-rate > 0");
  }
}

/// The band's degrees within 1..N-1 for W0's N.
void requireForcingBand(const Options& o, const Settings& s) {
  const ZeitlinStochasticForcing& f = s.forcing;
  const long n = static_cast<long>(s.W0.rows());
  if (f.forces() && !f.bandFits(n)) {
    app::usageError("--forcing-band", o.forcing_band,
                    "its degrees L-D..L+D must lie in [1, N-1], N = " + std::to_string(n));
  }
}

/// --forcing-file's Φ, of W0's N, into s.fixed_forcing, and a bound on what it can add:
/// |W0| + T |Φ| (Frobenius norms, T = steps · h) within kMaxForcedNorm, so that no energy or
/// enstrophy of the run overflows (both are below |W|²).
void readFixedForcing(const Options& o, Settings& s, Eigen::Index max_n) {
  if (o.forcing_file.empty()) return;
  Matrix phi = app::readSuNMatrixFile("--forcing-file", o.forcing_file, "Phi", {max_n, ""});
  const Eigen::Index n = s.W0.rows();
  if (phi.rows() != n) {
    app::usageError(
        "--forcing-file", o.forcing_file,
        "has N = " + std::to_string(phi.rows()) + "; the run's N is " + std::to_string(n));
  }
  s.fixed_forcing = std::move(phi);
}

void requireRepresentableForcing(const Options& o, const Settings& s) {
  if (s.fixed_forcing.size() == 0) return;
  const double reach =
      s.W0.stableNorm() + static_cast<double>(s.steps) * s.h * s.fixed_forcing.stableNorm();
  if (!(reach <= kMaxForcedNorm)) {
    app::usageError("--forcing-file", o.forcing_file,
                    fmt::format("|W0| + t |Phi| = {:.3g} at t = steps * h exceeds {:g}, where the "
                                "energy would overflow",
                                reach, kMaxForcedNorm));
  }
}

/// --rotation (finite) and --deformation-radius (> 0, finite) into s.physics; --viscosity,
/// --drag (finite, >= 0), --hyperviscosity-order and --viscous-scheme into s.viscosity.
void readPhysics(const Options& o, Settings& s) {
  s.physics.rotation = app::parseNumber("--rotation", o.rotation, o.rotation);
  if (!o.deformation_radius.empty()) {
    const double radius =
        app::parseNumber("--deformation-radius", o.deformation_radius, o.deformation_radius);
    if (!(radius > 0 && std::isfinite(radius))) {
      app::usageError("--deformation-radius", o.deformation_radius,
                      "must be finite and > 0 (leave it out for Euler flow)");
    }
    s.physics.deformation_radius = radius;
  }
  const auto nonNegative = [](const char* flag, const std::string& text) {
    const double value = app::parseNumber(flag, text, text);
    if (!(value >= 0 && std::isfinite(value)))
      app::usageError(flag, text, "must be finite and >= 0");
    return value;
  };
  s.viscosity.viscosity = nonNegative("--viscosity", o.viscosity);
  s.viscosity.drag = nonNegative("--drag", o.drag);
  if (o.hyperviscosity_order < 1 || o.hyperviscosity_order > kMaxHyperviscosityOrder) {
    app::usageError("--hyperviscosity-order", std::to_string(o.hyperviscosity_order),
                    "must be in [1, " + std::to_string(kMaxHyperviscosityOrder) + "]");
  }
  s.viscosity.order = static_cast<int>(o.hyperviscosity_order);
  app::requireChoice("--viscous-scheme", o.viscous_scheme, {"exact", "implicit"});
  s.viscosity.scheme = o.viscous_scheme == "implicit" ? ZeitlinViscousScheme::kImplicit
                                                      : ZeitlinViscousScheme::kExact;
  readForcing(o, s);
}

/// The text of a run-defining flag that the run took by default ("" if it has none).
std::string defaultText(const Checkpoint& c, const std::string& flag) {
  const Options& o = c.options;
  if (flag == "--n") return std::to_string(o.n);
  if (flag == "--alpha") return o.alpha;
  if (flag == "--rotation") return o.rotation;
  if (flag == "--viscosity") return o.viscosity;
  if (flag == "--drag") return o.drag;
  if (flag == "--hyperviscosity-order") return std::to_string(o.hyperviscosity_order);
  if (flag == "--viscous-scheme") return o.viscous_scheme;
  if (flag == "--forcing-rate") return o.forcing_rate;
  if (flag == "--forcing-seed") return std::to_string(o.forcing_seed);
  if (flag == "--method") return o.method;
  if (flag == "--init") return o.init;
  if (flag == "--every") return std::to_string(o.every);
  if (flag == "--seed") return std::to_string(o.seed);
  return "";
}

}  // namespace

Settings settings(const CLI::App& cli, const Options& o, Eigen::Index max_n) {
  Settings s;
  app::requireChoice("--method", o.method, app::namesOf(fluidMethods()));
  s.alpha = app::parseNumber("--alpha", o.alpha, o.alpha);
  readPhysics(o, s);
  const bool by_steps = cli.count("--steps") > 0, by_time = cli.count("--t-end") > 0;
  if (by_steps == by_time) {
    throw app::UsageError(std::string("--steps, --t-end: give exactly one of them (") +
                          (by_steps ? "both" : "neither") + " given)");
  }
  if (by_steps && (o.steps < 1 || o.steps > kMaxSteps)) {
    app::usageError("--steps", std::to_string(o.steps), "must be in [1, 1e9]");
  }
  if (o.every < 1) app::usageError("--every", std::to_string(o.every), "must be >= 1");
  if (cli.count("--checkpoint-every") > 0 && o.checkpoint_every < 1) {
    app::usageError("--checkpoint-every", std::to_string(o.checkpoint_every), "must be >= 1");
  }
  readRelaxOptions(cli, o, s);
  app::InitialVorticity initial =
      app::initialVorticity(cli, {o.n, o.seed, o.init, o.init_file}, {max_n, ""});
  s.W0 = std::move(initial.W);
  s.init = initial.init;
  requireForcingBand(o, s);
  readFixedForcing(o, s, max_n);

  double t_end = 0.0;
  if (by_time) {
    t_end = app::parseNumber("--t-end", o.t_end, o.t_end);
    if (!(t_end > 0)) app::usageError("--t-end", o.t_end, "must be > 0");
  }
  s.default_h = o.h.empty();
  if (s.default_h) {
    s.h = defaultStep(o, s);
  } else {
    s.h = app::parseNumber("--h", o.h, o.h);
    if (!(s.h > 0)) app::usageError("--h", o.h, "must be > 0");
  }
  s.steps = o.steps;
  // With --adaptive, --t-end caps the time and --steps the accepted steps; without,
  // both are the step count.
  const bool time_cap = by_time && o.relax.adaptive;
  if (time_cap) {
    // --h is only the first step, which the step control grows: any h > 0 can run, and the
    // cap is the time (and kMaxSteps accepted steps).
    s.steps = kMaxSteps;
  } else if (by_time) {
    // With the default h, equal steps that end exactly at T and are no longer than it.
    const double count = s.default_h ? std::ceil(t_end / s.h) : std::round(t_end / s.h);
    if (count > static_cast<double>(kMaxSteps)) {
      app::usageError("--t-end", o.t_end,
                      fmt::format("more than 1e9 steps of h = {} (or give --adaptive, whose --h "
                                  "is only the first step)",
                                  s.h));
    }
    s.steps = std::max(1L, static_cast<long>(count));
    if (s.default_h) s.h = t_end / static_cast<double>(s.steps);
  }
  requireRepresentableStep(cli, o, s);
  requireRepresentableForcing(o, s);
  s.relax.max_steps = s.steps;
  if (time_cap) s.relax.t_end = t_end;
  // Only valid input is warned about: bad input gives its one line and nothing else.
  const double reached = static_cast<double>(s.steps) * s.h;
  if (by_time && !time_cap && std::abs(reached - t_end) > 1e-9 * t_end) {
    spdlog::warn("--t-end {} is not a multiple of --h {}: {} steps end at t = {}", t_end, s.h,
                 s.steps, reached);
  }
  s.out = o.out;
  return s;
}

std::pair<std::string, std::string> exactFlowFlag(const Options& o, const Settings& s) {
  if (s.viscosity.viscosity > 0) return {"--viscosity", o.viscosity};
  if (s.viscosity.drag > 0) return {"--drag", o.drag};
  if (s.forcing.forces()) return {"--forcing-rate", o.forcing_rate};
  if (!o.forcing_file.empty()) return {"--forcing-file", o.forcing_file};
  return {};
}

void resumeSettings(const CLI::App& cli, const Options& given, Checkpoint& c) {
  // The run-defining flags given now must be those it ran with (givenFlags skips the others).
  for (const auto& [flag, text] : givenFlags(cli)) {
    // The value the run used: as given then, or the default it took.
    const auto recorded = c.given.find(flag);
    const std::string used = recorded != c.given.end() ? recorded->second : defaultText(c, flag);
    if (used != text) {
      app::usageError(flag, text,
                      "a resumed run keeps its settings (it ran with " + flag + " = " +
                          (used.empty() ? "none" : used) + ")");
    }
  }
  if (given.overwrite) {
    throw app::UsageError(
        "--overwrite: a resumed run continues the run in its folder; --overwrite is for a new "
        "run (--out)");
  }
  if (cli.count("--out") > 0 && std::filesystem::path(given.out).lexically_normal() !=
                                    std::filesystem::path(given.resume).lexically_normal()) {
    app::usageError("--out", given.out, "a resumed run writes into its --resume folder");
  }
  Options& o = c.options;
  Settings& s = c.settings;
  const bool by_steps = cli.count("--steps") > 0, by_time = cli.count("--t-end") > 0;
  if (by_steps && by_time) {
    throw app::UsageError("--steps, --t-end: give at most one of them with --resume (both given)");
  }
  if (by_steps) {
    if (given.steps < 1 || given.steps > kMaxSteps) {
      app::usageError("--steps", std::to_string(given.steps), "must be in [1, 1e9]");
    }
    o.steps = s.steps = s.relax.max_steps = given.steps;
    s.relax.t_end = std::numeric_limits<double>::infinity();
  }
  if (by_time && s.relax.newton) {
    throw app::UsageError("--t-end: a Newton search has no time (give --steps with --resume)");
  }
  if (by_time) {
    const double t_end = app::parseNumber("--t-end", given.t_end, given.t_end);
    if (!(t_end > 0)) app::usageError("--t-end", given.t_end, "must be > 0");
    o.t_end = given.t_end;
    if (s.relax.control.adaptive) {
      s.relax.max_steps = kMaxSteps;
      s.relax.t_end = t_end;
    } else {
      // The recorded h stays: round(T/h) of its steps (a warning if they do not end at T).
      const double count = std::round(t_end / s.h);
      if (count > static_cast<double>(kMaxSteps)) {
        app::usageError("--t-end", given.t_end, fmt::format("more than 1e9 steps of h = {}", s.h));
      }
      s.steps = s.relax.max_steps = std::max(1L, static_cast<long>(count));
      const double reached = static_cast<double>(s.steps) * s.h;
      if (std::abs(reached - t_end) > 1e-9 * t_end) {
        spdlog::warn("--t-end {} is not a multiple of the run's h {}: {} steps end at t = {}",
                     t_end, s.h, s.steps, reached);
      }
    }
  }
  if (cli.count("--checkpoint-every") > 0 && given.checkpoint_every < 1) {
    app::usageError("--checkpoint-every", std::to_string(given.checkpoint_every), "must be >= 1");
  }
  o.resume = given.resume;
  o.device = given.device;
  o.checkpoint_every = given.checkpoint_every;
  o.plot = given.plot;
  o.log = given.log;
  s.out = given.resume;
}

}  // namespace ddb::fluid
