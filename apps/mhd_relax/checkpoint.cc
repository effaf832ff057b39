#include "mhd_relax/checkpoint.h"

#include <spdlog/fmt/fmt.h>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/exit_status.h"
#include "common/journal_file.h"
#include "common/resume.h"
#include "common/run_folder.h"

namespace ddb::mhd {

namespace {

constexpr const char* kTag = "mhd-relax checkpoint";
constexpr std::int32_t kLayout = 1;

void putOptions(BinaryRecordWriter& out, const Options& o) {
  out.tag("options");
  for (const long v : {o.n, o.steps, o.every, o.theta_lmax}) out.put(v);
  for (const std::uint64_t v : {o.seed, o.theta_seed}) out.put(v);
  // Not --out: a run resumes in the folder it is in (moved or copied), and two runs of one
  // command in two folders write the same checkpoint.
  for (const std::string* text : {&o.alpha, &o.h, &o.t_end, &o.method, &o.init, &o.init_file,
                                  &o.theta_file, &o.theta_scale}) {
    out.put(*text);
  }
}

void getOptions(BinaryRecordReader& in, Options& o) {
  in.expectTag("options");
  for (long* v : {&o.n, &o.steps, &o.every, &o.theta_lmax}) in.get(*v);
  for (std::uint64_t* v : {&o.seed, &o.theta_seed}) in.get(*v);
  for (std::string* text : {&o.alpha, &o.h, &o.t_end, &o.method, &o.init, &o.init_file,
                            &o.theta_file, &o.theta_scale}) {
    in.get(*text);
  }
}

void putSettings(BinaryRecordWriter& out, const Settings& s) {
  out.tag("settings");
  out.put(s.W0);
  out.put(s.Theta0);
  out.put(s.alpha);
  out.put(s.h);
  app::putRelaxCaps(out, s.relax);
  out.put(s.init);
  out.put(s.theta_init);
}

void getSettings(BinaryRecordReader& in, Settings& s) {
  in.expectTag("settings");
  in.get(s.W0);
  in.get(s.Theta0);
  in.get(s.alpha);
  in.get(s.h);
  app::getRelaxCaps(in, s.relax);
  in.get(s.init);
  in.get(s.theta_init);
  if (s.W0.rows() < 2 || s.W0.rows() > kMaxN || s.W0.cols() != s.W0.rows() ||
      s.Theta0.rows() != s.W0.rows() || s.Theta0.cols() != s.W0.rows() || !(s.h > 0) ||
      s.relax.max_steps < 1) {
    throw CorruptRecord("settings out of their domain");
  }
}

void putNumbers(BinaryRecordWriter& out, const MhdFrameNumbers& n) {
  out.put(n.step);
  for (const double v : {n.t, n.kinetic_energy, n.magnetic_energy, n.cross_helicity, n.residual,
                         n.equilibrium_residual, n.invariant_drift}) {
    out.put(v);
  }
}

void getNumbers(BinaryRecordReader& in, MhdFrameNumbers& n) {
  in.get(n.step);
  for (double* v : {&n.t, &n.kinetic_energy, &n.magnetic_energy, &n.cross_helicity, &n.residual,
                    &n.equilibrium_residual, &n.invariant_drift}) {
    in.get(*v);
  }
}

}  // namespace

BinaryRecordWriter beginCheckpoint(const Options& o, const Settings& s, const Tally& tally,
                                   const FileLengths& files) {
  BinaryRecordWriter out;
  out.tag(kTag);
  out.put(kLayout);
  putOptions(out, o);
  putSettings(out, s);
  out.tag("tally");
  putNumbers(out, tally.first);
  out.put(tally.drift_max);
  out.put(tally.iterations_total);
  out.put(tally.iterations_max);
  tally.rises.save(out);
  out.tag("files");
  out.put(files.history_bytes);
  out.put(files.history_digest);
  out.put(files.frames);
  return out;
}

void writeCheckpoint(const std::filesystem::path& out, const BinaryRecordWriter& record) {
  app::writeFileAtomically(out / kCheckpointFile, record.sealed());
}

Checkpoint readCheckpoint(const std::string& dir) {
  const std::filesystem::path path = std::filesystem::path(dir) / kCheckpointFile;
  if (!std::filesystem::exists(path)) {
    app::usageError("--resume", dir, "no checkpoint to resume from: " + path.string());
  }
  Checkpoint c;
  try {
    BinaryRecordReader in = BinaryRecordReader::unseal(app::readRegularFile("--resume", dir, path));
    in.expectTag(kTag);
    const auto layout = in.get<std::int32_t>();
    if (layout != kLayout) {
      throw CorruptRecord("layout " + std::to_string(layout) + ", this build reads " +
                          std::to_string(kLayout));
    }
    getOptions(in, c.options);
    getSettings(in, c.settings);
    in.expectTag("tally");
    getNumbers(in, c.tally.first);
    in.get(c.tally.drift_max);
    in.get(c.tally.iterations_total);
    in.get(c.tally.iterations_max);
    c.tally.rises.load(in);
    in.expectTag("files");
    in.get(c.files.history_bytes);
    in.get(c.files.history_digest);
    in.get(c.files.frames);
    c.relaxation = std::move(in);
  } catch (const CorruptRecord& corrupt) {
    app::usageError("--resume", dir,
                    path.string() + " is corrupt (" + corrupt.what() + "): refusing to use it");
  }
  c.settings.out = dir;
  return c;
}

void checkResumeFolder(const std::string& dir, const Checkpoint& c) {
  const std::filesystem::path folder(dir);
  const std::filesystem::path history = app::JournalFile::resumeFileOf(folder / "history.csv");
  const std::uint64_t size = app::requireRegularFile("--resume", dir, history);
  const std::uint64_t recorded = c.files.history_bytes;
  if (size < recorded ||
      app::digestOfPrefix("--resume", dir, history, recorded) != c.files.history_digest) {
    app::usageError("--resume", dir,
                    history.string() + " is not the history its checkpoint continues (its first " +
                        std::to_string(recorded) +
                        " bytes are not those the run wrote): another run's, or altered");
  }
  try {
    MhdH5::checkResumable(folder / "fluid.hdf5", c.settings.W0.rows(), c.files.frames);
  } catch (const app::IoError& error) {
    app::usageError("--resume", dir, std::string(error.what()) + ": refusing to resume into it");
  }
}

}  // namespace ddb::mhd
