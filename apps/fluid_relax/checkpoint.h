// fluid-relax's checkpoints (docs/reference/command-lines-and-files.md, "Checkpoints"):
// OUT/checkpoint.ddb, one checksummed BinaryRecord (core/binary_record.h) written atomically
// (AtomicFile: a temporary, fsync, rename), holding everything a resumed run needs to continue the
// uninterrupted one to the bit: the command line as given, the validated settings (W₀
// included, so that a changed --init-file cannot change a resumed run), what the summary
// accumulates, the lengths of the files that grow (history.csv with the hash of its bytes,
// fluid.hdf5's frames), and the relaxation's cursor with the method's warm start
// (Relaxation::save). A resume checks the folder against it before it changes anything
// (fluid_relax/run_files.h).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/groups/sun.h>
#include <ddb/integrators/drivers/relax.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "common/energy_rises.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"

namespace ddb::fluid {

constexpr const char* kCheckpointFile = "checkpoint.ddb";

/// The flags of a command line that define the run, as given: name → value text. The
/// others (--out, --resume, --overwrite, --steps, --t-end, --checkpoint-every, --plot,
/// --verbose, --quiet) do not change the states a run computes, and fluid-relax's --device and
/// fluid-relax-mpi's --block and --grid-rows change them by rounding only, as the number of ranks
/// does: a resumed run may give them anew, and a checkpoint does not record them, so that it is
/// the same whatever they were.
using GivenFlags = std::map<std::string, std::string>;
GivenFlags givenFlags(const CLI::App& cli);

/// What summary.json accumulates over every step.
struct Tally {
  double drift = 0.0, drift_max = 0.0;  // spectrum drift of the last state, the largest
  long iterations_total = 0, iterations_max = 0;
  app::EnergyRises rises;
};

/// Where the files that grow stood at a checkpoint's state.
struct FileLengths {
  std::uint64_t history_bytes = 0;  // history.csv's rows up to the state
  /// The FNV-1a hash of those bytes (JournalFile::digest), by which a resume knows the file
  /// for this run's: absent from the checkpoints of layout 2, which a resume still reads.
  std::optional<std::uint64_t> history_digest;
  std::int64_t h5_frames = 0;  // fluid.hdf5's frames likewise (0 without --h5)
  /// Whether history.csv has the gamma column and fluid.hdf5 the field diagnostics: not in
  /// the files of a run begun with a checkpoint layout before 5, which keep their columns when
  /// resumed (and record false from then on).
  bool field_diagnostics = true;
};

/// A checkpoint as read back; `relaxation` is positioned at the relaxation's record.
struct Checkpoint {
  Options options;
  GivenFlags given;
  Settings settings;
  Tally tally;
  FileLengths files;
  BinaryRecordReader relaxation{""};
};

/// A checkpoint up to the relaxation's record, which the caller appends (Relaxation::save,
/// or fluid-relax-mpi's writer of the same record) before writeCheckpoint().
BinaryRecordWriter beginCheckpoint(const Options& o, const GivenFlags& given, const Settings& s,
                                   const Tally& tally, const FileLengths& files);

/// Writes OUT/checkpoint.ddb atomically; throws IoError naming it.
void writeCheckpoint(const std::filesystem::path& out, const BinaryRecordWriter& record);

/// The options, the given flags and the settings but W₀, written and read as the checkpoint
/// writes and reads them: what fluid-relax-mpi's rank 0 sends the other ranks, which hold
/// no W₀ (docs/design/distributed.md, "Memory per rank").
void putRunDefinition(BinaryRecordWriter& out, const Options& o, const GivenFlags& given,
                      const Settings& s);
void getRunDefinition(BinaryRecordReader& in, Options& o, GivenFlags& given, Settings& s);

/// DIR/checkpoint.ddb for `--resume DIR`; a missing, unreadable, truncated or corrupted one
/// (its checksum, a size beyond the file, a setting out of its domain), or one that is not a
/// regular file (a FIFO, a device, a folder), is a UsageError naming --resume and the file.
Checkpoint readCheckpoint(const std::string& dir);

}  // namespace ddb::fluid
