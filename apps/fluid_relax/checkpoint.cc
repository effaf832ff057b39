#include "fluid_relax/checkpoint.h"

#include <cmath>
#include <iterator>
#include <set>
#include <sstream>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/exit_status.h"
#include "common/resume.h"
#include "common/run_folder.h"

namespace ddb::fluid {

namespace {

// The layout's version: a checkpoint of another layout is refused, not misread. Each layout adds
// entries to the one before: layout 3 history.csv's hash, layout 4 the fluid's physics
// (--rotation, --deformation-radius), layout 5 its damping (--viscosity, --hyperviscosity-order,
// --drag) and the field diagnostics of the files (history.csv's gamma, fluid.hdf5's spectra, scale
// decomposition and grid), layout 6 its forcing (--forcing-band, --forcing-rate, --forcing-seed;
// the random stream's position is in the method's record, ExactFlow::save), layout 7 a fixed
// forcing (--forcing-file and its Φ), layout 8 the viscous flow's scheme (--viscous-scheme). A
// checkpoint of layout 2 to 7 is still read (without what came later: no hash, a resting sphere,
// undamped, unforced, exact, files without the diagnostics), so that a run begun by an earlier
// build resumes.
constexpr std::int32_t kLayout = 8;
constexpr std::int32_t kOldestLayout = 2;
constexpr std::int32_t kLayoutWithDigest = 3;
constexpr std::int32_t kLayoutWithPhysics = 4;
constexpr std::int32_t kLayoutWithDamping = 5;
constexpr std::int32_t kLayoutWithForcing = 6;
constexpr std::int32_t kLayoutWithFixedForcing = 7;
constexpr std::int32_t kLayoutWithViscousScheme = 8;
constexpr const char* kTag = "fluid-relax checkpoint";

void putOptions(BinaryRecordWriter& out, const Options& o) {
  out.tag("options");
  out.put(o.n);
  out.put(o.steps);
  out.put(o.every);
  out.put(o.seed);
  for (const std::string* text : {&o.alpha, &o.h, &o.t_end, &o.init, &o.init_file, &o.method,
                                  &o.relax.until_steady, &o.relax.adaptive_tol}) {
    out.put(*text);
  }
  out.put(o.relax.adaptive);
  out.put(o.newton);
  out.put(o.h5);
  out.put(o.animate);
  out.put(o.rotation);
  out.put(o.deformation_radius);
  out.put(o.viscosity);
  out.put(o.hyperviscosity_order);
  out.put(o.drag);
  out.put(o.forcing_band);
  out.put(o.forcing_rate);
  out.put(o.forcing_seed);
  out.put(o.forcing_file);
  out.put(o.viscous_scheme);
}

/// The options of a record of `layout` (those it lacks keep their defaults).
void getOptions(BinaryRecordReader& in, Options& o, std::int32_t layout) {
  in.expectTag("options");
  in.get(o.n);
  in.get(o.steps);
  in.get(o.every);
  in.get(o.seed);
  for (std::string* text : {&o.alpha, &o.h, &o.t_end, &o.init, &o.init_file, &o.method,
                            &o.relax.until_steady, &o.relax.adaptive_tol}) {
    in.get(*text);
  }
  in.get(o.relax.adaptive);
  in.get(o.newton);
  in.get(o.h5);
  in.get(o.animate);
  if (layout >= kLayoutWithPhysics) {
    in.get(o.rotation);
    in.get(o.deformation_radius);
  }
  if (layout >= kLayoutWithDamping) {
    in.get(o.viscosity);
    in.get(o.hyperviscosity_order);
    in.get(o.drag);
  }
  if (layout >= kLayoutWithForcing) {
    in.get(o.forcing_band);
    in.get(o.forcing_rate);
    in.get(o.forcing_seed);
  }
  if (layout >= kLayoutWithFixedForcing) in.get(o.forcing_file);
  if (layout >= kLayoutWithViscousScheme) in.get(o.viscous_scheme);
  // What a command line could not have given (a record altered and its checksum made anew).
  if (o.every < 1 || o.steps < 0 || o.steps > kMaxSteps ||
      (o.viscous_scheme != "exact" && o.viscous_scheme != "implicit")) {
    throw CorruptRecord("options out of their domain");
  }
}

void putGivenFlags(BinaryRecordWriter& out, const GivenFlags& given) {
  out.tag("given flags");
  out.put(static_cast<std::uint64_t>(given.size()));
  for (const auto& [flag, text] : given) {
    out.put(flag);
    out.put(text);
  }
}

void getGivenFlags(BinaryRecordReader& in, GivenFlags& given) {
  in.expectTag("given flags");
  const auto count = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string flag = in.get<std::string>();
    given[flag] = in.get<std::string>();
  }
}

// The settings but W₀ (which the record holds before them).
void putSettingsBesidesW0(BinaryRecordWriter& out, const Settings& s) {
  out.put(s.alpha);
  out.put(s.h);
  out.put(s.default_h);
  out.put(s.steps);
  app::putRelaxCaps(out, s.relax);
  out.put(s.relax.newton);
  out.put(s.init);
  out.put(s.physics.rotation);
  out.put(s.physics.deformation_radius);
  out.put(s.viscosity.viscosity);
  out.put(static_cast<std::int32_t>(s.viscosity.order));
  out.put(s.viscosity.drag);
  out.put(static_cast<std::int32_t>(s.forcing.band_centre));
  out.put(static_cast<std::int32_t>(s.forcing.band_half_width));
  out.put(s.forcing.rate);
  out.put(s.forcing.seed);
  out.put(s.fixed_forcing);
  out.put(static_cast<std::int32_t>(s.viscosity.scheme));
}

void getSettingsBesidesW0(BinaryRecordReader& in, Settings& s, std::int32_t layout) {
  in.get(s.alpha);
  in.get(s.h);
  in.get(s.default_h);
  in.get(s.steps);
  app::getRelaxCaps(in, s.relax);
  in.get(s.relax.newton);
  in.get(s.init);
  if (layout >= kLayoutWithPhysics) {
    in.get(s.physics.rotation);
    in.get(s.physics.deformation_radius);
  }
  if (layout >= kLayoutWithDamping) {
    in.get(s.viscosity.viscosity);
    s.viscosity.order = in.get<std::int32_t>();
    in.get(s.viscosity.drag);
  }
  if (layout >= kLayoutWithForcing) {
    s.forcing.band_centre = in.get<std::int32_t>();
    s.forcing.band_half_width = in.get<std::int32_t>();
    in.get(s.forcing.rate);
    in.get(s.forcing.seed);
  }
  if (layout >= kLayoutWithFixedForcing) in.get(s.fixed_forcing);
  std::int32_t scheme = 0;
  if (layout >= kLayoutWithViscousScheme) in.get(scheme);
  if (scheme != 0 && scheme != 1) throw CorruptRecord("settings out of their domain");
  s.viscosity.scheme = scheme == 1 ? ZeitlinViscousScheme::kImplicit : ZeitlinViscousScheme::kExact;
  const ZeitlinViscosity& v = s.viscosity;
  const ZeitlinStochasticForcing& f = s.forcing;
  const bool in_domain =
      std::isfinite(s.alpha) && s.h > 0 && std::isfinite(s.h) && s.steps >= 1 &&
      s.steps <= kMaxSteps && s.relax.max_steps >= 1 && s.relax.max_steps <= kMaxSteps &&
      s.relax.tolerance >= 0 && s.relax.tolerance < 1 && !(s.relax.t_end <= 0) &&
      s.relax.control.tolerance > 0 && s.relax.control.tolerance < 1 &&
      std::isfinite(s.physics.rotation) && s.physics.deformation_radius > 0 && v.viscosity >= 0 &&
      std::isfinite(v.viscosity) && v.order >= 1 && v.order <= kMaxHyperviscosityOrder &&
      v.drag >= 0 && std::isfinite(v.drag) && f.rate >= 0 && std::isfinite(f.rate) &&
      f.band_half_width >= 0 && (!f.forces() || long(f.band_centre) - f.band_half_width >= 1);
  if (!in_domain) throw CorruptRecord("settings out of their domain");
}

void putSettings(BinaryRecordWriter& out, const Settings& s) {
  out.tag("settings");
  out.put(s.W0);
  putSettingsBesidesW0(out, s);
}

void getSettings(BinaryRecordReader& in, Settings& s, std::int32_t layout) {
  in.expectTag("settings");
  in.get(s.W0);
  getSettingsBesidesW0(in, s, layout);
  if (s.W0.rows() < 2 || s.W0.rows() > SUN::kMaxN || s.W0.rows() != s.W0.cols() ||
      (s.forcing.forces() && !s.forcing.bandFits(s.W0.rows())) ||
      // Φ is 0 x 0 (none) or N x N and finite.
      (s.fixed_forcing.size() == 0
           ? s.fixed_forcing.rows() != 0 || s.fixed_forcing.cols() != 0
           : s.fixed_forcing.rows() != s.W0.rows() || s.fixed_forcing.cols() != s.W0.rows() ||
                 !s.fixed_forcing.allFinite())) {
    throw CorruptRecord("settings out of their domain");
  }
}

std::string readCheckpointBytes(const std::string& dir) {
  // Its existence was checked with the folder's lock (lockResumeFolder).
  return app::readRegularFile("--resume", dir, std::filesystem::path(dir) / kCheckpointFile);
}

// The checkpoint in `bytes`, read from DIR for `--resume DIR`; a truncated or corrupted one
// (its checksum) is a UsageError naming --resume and the file.
Checkpoint parseCheckpoint(const std::string& dir, std::string bytes) {
  const std::filesystem::path path = std::filesystem::path(dir) / kCheckpointFile;
  Checkpoint c;
  try {
    BinaryRecordReader in = BinaryRecordReader::unseal(std::move(bytes));
    in.expectTag(kTag);
    const auto layout = in.get<std::int32_t>();
    if (layout < kOldestLayout || layout > kLayout) {
      throw CorruptRecord("layout " + std::to_string(layout) + ", this build reads " +
                          std::to_string(kLayout));
    }
    getOptions(in, c.options, layout);
    getGivenFlags(in, c.given);
    getSettings(in, c.settings, layout);
    in.expectTag("tally");
    in.get(c.tally.drift);
    in.get(c.tally.drift_max);
    in.get(c.tally.iterations_total);
    in.get(c.tally.iterations_max);
    c.tally.rises.load(in);
    in.expectTag("files");
    in.get(c.files.history_bytes);
    in.get(c.files.h5_frames);
    if (layout >= kLayoutWithDigest) c.files.history_digest = in.get<std::uint64_t>();
    const auto diagnostics =
        layout >= kLayoutWithDamping ? in.get<std::uint8_t>() : std::uint8_t{0};
    if (diagnostics > 1) throw CorruptRecord("files out of their domain");
    c.files.field_diagnostics = diagnostics == 1;
    if (c.files.h5_frames < 0 || (c.files.h5_frames > 0 && !(c.options.h5 || c.options.animate))) {
      throw CorruptRecord("files out of their domain");
    }
    c.relaxation = std::move(in);
  } catch (const CorruptRecord& corrupt) {
    app::usageError("--resume", dir,
                    path.string() + " is corrupt (" + corrupt.what() + "): refusing to use it");
  }
  return c;
}

}  // namespace

GivenFlags givenFlags(const CLI::App& cli) {
  GivenFlags given;
  for (const CLI::Option* option : cli.get_options()) {
    static const std::set<std::string> kFree{
        "--out",     "--resume", "--steps", "--t-end",     "--checkpoint-every", "--plot",
        "--verbose", "--quiet",  "--block", "--grid-rows", "--overwrite",        "--device"};
    if (option->count() == 0 || kFree.count(option->get_name()) > 0) continue;
    std::string text;
    for (const std::string& result : option->results()) text += (text.empty() ? "" : ",") + result;
    given[option->get_name()] = text;
  }
  return given;
}

BinaryRecordWriter beginCheckpoint(const Options& o, const GivenFlags& given, const Settings& s,
                                   const Tally& tally, const FileLengths& files) {
  BinaryRecordWriter record;
  record.tag(kTag);
  record.put(kLayout);
  putOptions(record, o);
  putGivenFlags(record, given);
  putSettings(record, s);
  record.tag("tally");
  record.put(tally.drift);
  record.put(tally.drift_max);
  record.put(tally.iterations_total);
  record.put(tally.iterations_max);
  tally.rises.save(record);
  record.tag("files");
  record.put(files.history_bytes);
  record.put(files.h5_frames);
  record.put(files.history_digest.value_or(kFnv1a64Basis));
  record.put(static_cast<std::uint8_t>(files.field_diagnostics ? 1 : 0));
  return record;
}

void putRunDefinition(BinaryRecordWriter& out, const Options& o, const GivenFlags& given,
                      const Settings& s) {
  putOptions(out, o);
  putGivenFlags(out, given);
  putSettingsBesidesW0(out, s);
}

void getRunDefinition(BinaryRecordReader& in, Options& o, GivenFlags& given, Settings& s) {
  getOptions(in, o, kLayout);
  getGivenFlags(in, given);
  getSettingsBesidesW0(in, s, kLayout);
}

void writeCheckpoint(const std::filesystem::path& out, const BinaryRecordWriter& record) {
  app::writeFileAtomically(out / kCheckpointFile, record.sealed());
}

Checkpoint readCheckpoint(const std::string& dir) {
  return parseCheckpoint(dir, readCheckpointBytes(dir));
}

}  // namespace ddb::fluid
