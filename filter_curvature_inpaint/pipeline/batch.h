// Whole collections: the main job over a manifest of scans, resumable and shardable, so that a
// lab's thousands of scans go through one command or one Slurm job array. Each scan's result
// is written atomically and recorded as one JSON line once it is complete; a batch killed at
// any moment loses no finished scan, and running it again does only what is left.
#pragma once

#include "pipeline/hole_fill.h"

#include <functional>
#include <string>
#include <vector>

namespace curvature_inpaint {

/// One scan of a manifest, with the fill options of its line (text manifests only).
struct BatchScan {
  std::string input;
  std::vector<std::string> options;
};

/// The scans of `manifest`: every .ply, .obj, .off and .stl file of a folder (by name), or the
/// lines of a text file, each a path (relative to the file's folder) and optionally fill
/// options (`#` starts a comment). Throws std::runtime_error for a manifest that cannot be
/// read, or two scans that would write the same output.
std::vector<BatchScan> ReadManifest(const std::string& manifest);

struct BatchParams {
  std::string outdir;
  std::vector<std::string> options; ///< fill options for every scan (before a line's own)
  int jobs = 1;                     ///< scans at once; each gets cores / jobs threads
  int shard = 0, shards = 1;        ///< this task takes the scans with index % shards == shard
  bool progress_bar = false;        ///< a bar on a terminal instead of one line per scan
};

/// Turns fill options into parameters (the command-line tool's parser). Throws for a bad one.
using FillOptionParser = std::function<HoleFillParams(const std::vector<std::string>& options)>;

struct BatchSummary {
  int scans = 0, done = 0, skipped = 0, failed = 0;
};

/// Fills this shard's scans into params.outdir (each under its input's name) and appends one
/// line per scan to its results file (results.jsonl, or results.K-of-N.jsonl for shard K of
/// N). A scan whose output and successful result line exist for the same input bytes
/// (SHA-256) and options is skipped. A scan that fails is recorded with its reason and the
/// batch goes on. Throws std::runtime_error only where the batch cannot run at all (no
/// output folder, unreadable manifest, bad options for every scan).
BatchSummary RunBatch(const std::vector<BatchScan>& scans, const BatchParams& params,
                      const FillOptionParser& parse);

/// The results of every shard in `outdir` as a Markdown table on stdout (scans, holes,
/// failures with their reasons, seconds per scan), and `outdir`/summary.csv with one row per
/// scan. Returns the number of failed scans. Throws std::runtime_error when there are none.
int SummarizeBatch(const std::string& outdir);

} // namespace curvature_inpaint
