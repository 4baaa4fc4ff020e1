// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What `lightcone animate` renders: a path (core/scene/animation.hpp) through scenes, one scene
// per frame. Per frame the scene goes through the same checks as a scene file, and what does not
// change between frames (the world line, textures, meshes) is computed once.
#include "core/scene/animation.hpp"
#include "readers/io/scene_edits.hpp"

#include <optional>
#include <string>
#include <vector>

namespace lc::cli {

// FROM:TO:FRAMES (--proper-time, --pan, --orbit). Throws std::invalid_argument naming `option`
// and the accepted ranges.
FrameInterval parseFrameInterval(const std::string& option, const std::string& text, const input::Range& range);
// FIELD=FROM:TO:FRAMES (--sweep).
FieldSweep parseFieldSweep(const std::string& option, const std::string& text);

// A printf pattern with one frame-number conversion ("frames/%04d.png"; "%%" is a literal %).
class FramePattern {
public:
    FramePattern() = default;
    // Throws std::invalid_argument naming `option` unless there is exactly one %d or %0Nd.
    FramePattern(const std::string& pattern, const std::string& option);
    std::string path(int frame) const;
    const std::string& pattern() const { return pattern_; }
    bool empty() const { return pattern_.empty(); }

private:
    std::string pattern_, before_, after_;
    int width_ = 0;
};

// Frame files go into the pattern's folder, made here when its parent exists (-o frames/%04d.png);
// the first frame's path is checked against `extensions` (animate, shade --sweep).
void prepareFrameFolder(const FramePattern& pattern, const std::string& option,
                        const std::vector<std::string>& extensions);

class FrameSequence {
public:
    // `base`: the scene as read (file or session). `adjust` is applied to every frame's scene last
    // (the command line's --width, --method, ...). Throws as the first bad frame would, so a path
    // that leaves the scene's accepted ranges fails before any frame is rendered.
    FrameSequence(io::EditableScene base, AnimationPath path, std::function<void(Scene&)> adjust);
    int size() const { return frames_; }
    const AnimationPath& path() const { return path_; }
    // The scene of frame k (0 <= k < size()); thread-safe.
    Scene scene(int frame) const;

private:
    Scene sweptScene(int frame) const;
    void moveObserver(Scene& scene, int frame) const;

    io::EditableScene base_;
    AnimationPath path_;
    std::function<void(Scene&)> adjust_;
    int frames_ = 0;
    std::vector<ObserverEvent> worldLine_;  // per frame, when the metric does not change between frames
};

}  // namespace lc::cli
