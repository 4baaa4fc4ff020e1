// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Renders frames of a sequence over every process of the run (app/distributed: MPI ranks under
// mpirun, else this one). Per-pixel methods (numeric, closed form) split a frame into bands of
// rows, so a frame's rays near a black hole spread over all ranks; the rasterising methods
// (per vertex, special relativity, shaders) render a whole frame per task. Rank 0 assembles the
// bands, shades them and hands each finished frame to the caller: the same pixels as one
// process, byte for byte, since every pixel is traced alone.
#include "app/distributed/distributed_tasks.hpp"
#include "app/commands/frame_sequence.hpp"
#include "core/render/special_relativity.hpp"

#include <functional>

namespace lc::cli {

struct FrameRenderOptions {
    bool polygonDistortion = false;
    bool gpu = false;
    int bandRows = 0;  // rows per band when distributed; 0: 8, fewer for small images (about 8 bands a rank)
    dist::Schedule schedule = dist::Schedule::Dynamic;
    // Bands travel as their per-pixel records (44 bytes a pixel, for --data and statistics), or
    // shaded where they were traced, as colours only (12 bytes a pixel).
    bool keepRecords = true;
    // A frame whose outputs already exist is skipped (--resume); checked by the rank that gets it.
    std::function<bool(int frame)> alreadyDone;
    // Fraction of the frames done, on rank 0 (main thread).
    std::function<void(double)> progress;
};

struct FramesReport {
    dist::TaskReport tasks;
    int rendered = 0, skipped = 0, bandsPerFrame = 1;
};

// Renders the frames `frames` of `sequence`; on rank 0 calls done(frame, image) for each
// rendered frame once all its bands are in (in completion order). Throws dist::TaskFailed when
// any rank fails (the message names the rank and the frame).
FramesReport renderFrames(const FrameSequence& sequence, const std::vector<int>& frames,
                          const FrameRenderOptions& options,
                          const std::function<void(int frame, ColouredImage&& image)>& done);

// What each rank did, for rank 0 to print when the run was distributed: tasks, busy time,
// bytes sent, the imbalance (slowest rank's busy time over the mean) and the bytes per frame.
void printTaskReport(const dist::TaskReport& report, int frames);

}  // namespace lc::cli
