// mhd-relax's checkpoints (docs/reference/command-lines-and-files.md, "mhd-relax"):
// OUT/checkpoint.ddb, one checksummed BinaryRecord (core/binary_record.h) written atomically,
// holding what a resumed run needs to continue the uninterrupted one to the bit: the options that
// define the run and its validated settings (W₀ and Θ₀ included), what the summary accumulates,
// the lengths of the files that grow (history.csv with the hash of its bytes, fluid.hdf5's
// frames) and the relaxation's cursor (Relaxation::save).
#pragma once

#include <ddb/core/binary_record.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "common/energy_rises.h"
#include "mhd_relax/mhd_h5.h"
#include "mhd_relax/options.h"

namespace ddb::mhd {

constexpr const char* kCheckpointFile = "checkpoint.ddb";

/// What summary.json accumulates over the run.
struct Tally {
  MhdFrameNumbers first;  // the first row's numbers
  double drift_max = 0.0;
  long iterations_total = 0, iterations_max = 0;
  app::EnergyRises rises;
};

/// Where the files that grow stood at a checkpoint's state.
struct FileLengths {
  std::uint64_t history_bytes = 0, history_digest = kFnv1a64Basis;
  std::int64_t frames = 0;
};

/// A checkpoint as read back; `relaxation` is positioned at the relaxation's record.
struct Checkpoint {
  Options options;
  Settings settings;
  Tally tally;
  FileLengths files;
  BinaryRecordReader relaxation{""};
};

/// A checkpoint up to the relaxation's record, which the caller appends (Relaxation::save).
BinaryRecordWriter beginCheckpoint(const Options& o, const Settings& s, const Tally& tally,
                                   const FileLengths& files);

/// Writes OUT/checkpoint.ddb atomically; throws IoError naming it.
void writeCheckpoint(const std::filesystem::path& out, const BinaryRecordWriter& record);

/// DIR/checkpoint.ddb for `--resume DIR`; a missing, unreadable, truncated or corrupted one is a
/// UsageError naming --resume and the file.
Checkpoint readCheckpoint(const std::string& dir);

/// Checks, reading only, that DIR's history.csv (or the .partial a killed run left) begins with
/// the checkpoint's bytes, and that its fluid.hdf5 (or .partial) holds its frames: a UsageError
/// naming --resume and the file otherwise.
void checkResumeFolder(const std::string& dir, const Checkpoint& c);

}  // namespace ddb::mhd
