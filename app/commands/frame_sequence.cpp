// SPDX-License-Identifier: BSD-3-Clause
// Frame paths of `lightcone animate`: parsing, frame-file patterns and each frame's scene.
#include "app/commands/frame_sequence.hpp"

#include "app/cli/cli_args.hpp"
#include "core/input/number_text.hpp"
#include "core/scene/frame_camera.hpp"
#include "readers/io/atomic_output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace lc::cli {
namespace {

std::vector<std::string> splitColons(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t k = 0; k <= text.size(); ++k)
        if (k == text.size() || text[k] == ':') {
            parts.push_back(text.substr(start, k - start));
            start = k + 1;
        }
    return parts;
}

// Rotation by `angle` (radians) about the unit axis, right-handed (Rodrigues).
Vec3 rotated(const Vec3& v, const Vec3& axis, double angle) {
    return std::cos(angle) * v + std::sin(angle) * axis.cross(v) + (1 - std::cos(angle)) * axis.dot(v) * axis;
}

enum class Chart { Cartesian, Cylindrical, Other };
Chart chartOf(const Spacetime& st) {
    const auto names = st.coordinateNames();
    if (names[1] == "x" && names[2] == "y" && names[3] == "z") return Chart::Cartesian;
    if (names[1] == "r" && names[2] == "phi" && names[3] == "z") return Chart::Cylindrical;
    return Chart::Other;
}

void orbit(Scene& scene, double degrees) {
    const double angle = degrees * kPi / 180;
    switch (chartOf(*scene.spacetime)) {
        case Chart::Cartesian: {
            // The event, the velocity and the camera's chart directions turn together.
            auto turn = [&](const Vec3& v) { return rotated(v, Vec3::UnitZ(), angle); };
            scene.observer.tail<3>() = turn(scene.observer.tail<3>()).eval();
            scene.observerVelocity.tail<3>() = turn(scene.observerVelocity.tail<3>()).eval();
            scene.camera.forward = turn(scene.camera.forward);
            scene.camera.up = turn(scene.camera.up);
            break;
        }
        case Chart::Cylindrical: scene.observer(2) += angle; break;  // the frame turns with phi
        case Chart::Other:
            throw std::invalid_argument("--orbit needs a chart with coordinates (t, x, y, z) or (t, r, phi, z); " +
                                        scene.spacetime->name() + " has neither");
    }
}

void pan(Scene& scene, double degrees) {
    scene.camera.forward = turnedForward(scene, degrees * kPi / 180);  // positive: to the left, as the observer turns
    scene.camera.lookAt.reset();                                       // turned away from the point
}

TraceOptions worldLineAccuracy() {
    TraceOptions opt;
    opt.absTol = opt.relTol = 1e-12;
    return opt;
}

}  // namespace

FrameInterval parseFrameInterval(const std::string& option, const std::string& text, const input::Range& range) {
    const auto parts = splitColons(text);
    if (parts.size() != 3)
        throw std::invalid_argument("option " + option + " expects FROM:TO:FRAMES, got '" + text + "'");
    FrameInterval v;
    v.from = parseNamedNumber(option + " (FROM)", parts[0], range);
    v.to = parseNamedNumber(option + " (TO)", parts[1], range);
    v.frames = static_cast<int>(parseNamedNumber(option + " (FRAMES)", parts[2], input::kAnimationFrames));
    return v;
}

FieldSweep parseFieldSweep(const std::string& option, const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw std::invalid_argument("option " + option +
                                    " expects FIELD=FROM:TO:FRAMES (e.g. metric.a=0.5:2:60), got '" + text + "'");
    static const input::Range anyField{"scene field", -1e12, 1e12, false, "", ""};
    const std::string field = text.substr(0, eq);
    if (field.rfind("animation", 0) == 0)
        throw std::invalid_argument("option " + option + ": a sweep cannot change the animation itself");
    return {field, parseFrameInterval(option, text.substr(eq + 1), anyField)};
}

FramePattern::FramePattern(const std::string& pattern, const std::string& option) : pattern_(pattern) {
    int conversions = 0;
    std::string literal;
    for (std::size_t k = 0; k < pattern.size(); ++k) {
        if (pattern[k] != '%') {
            literal += pattern[k];
            continue;
        }
        if (k + 1 < pattern.size() && pattern[k + 1] == '%') {
            literal += '%';
            ++k;
            continue;
        }
        std::size_t end = k + 1;
        int width = 0;
        if (end < pattern.size() && pattern[end] == '0') ++end;
        if (end < pattern.size() && pattern[end] >= '1' && pattern[end] <= '9') width = pattern[end++] - '0';
        if (end >= pattern.size() || pattern[end] != 'd')
            throw std::invalid_argument("option " + option + ": '" + pattern +
                                        "' may hold only %d or %0Nd (N 1 to 9) and %% (a literal %)");
        if (++conversions > 1) break;
        before_ = literal;
        literal.clear();
        width_ = width;
        k = end;
    }
    if (conversions != 1)
        throw std::invalid_argument("option " + option + ": '" + pattern +
                                    "' needs exactly one frame number, e.g. frames/%04d.png");
    if (literal.find('/') != std::string::npos)
        throw std::invalid_argument("option " + option + ": '" + pattern +
                                    "': the frame number belongs in the file name, not in a folder");
    after_ = literal;
}

std::string FramePattern::path(int frame) const {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%0*d", width_, frame);
    return before_ + digits + after_;
}

FrameSequence::FrameSequence(io::EditableScene base, AnimationPath path, std::function<void(Scene&)> adjust)
    : base_(std::move(base)), path_(std::move(path)), adjust_(std::move(adjust)), frames_(path_.frames()) {
    if (path_.properTime && !path_.sweep) {
        const Scene& s = base_.scene();
        std::vector<double> taus;
        for (int k = 0; k < frames_; ++k) taus.push_back(path_.properTime->at(k));
        worldLine_ = observerWorldLine(*s.spacetime, s.observer, s.observerVelocity,
                                       path_.motion.value_or(defaultObserverMotion(s.observerVelocity)), taus,
                                       worldLineAccuracy());
    }
    // Every frame is read once here, so that a path leaving the accepted ranges between its
    // ends (a horizon, an ergoregion) fails before any frame is rendered. Moves of the observer
    // alone are cheap; a sweep re-reads the scene file per frame.
    for (int k = 0; k < frames_; ++k) scene(k);
}

void prepareFrameFolder(const FramePattern& pattern, const std::string& option,
                        const std::vector<std::string>& extensions) {
    const std::filesystem::path first(pattern.path(0));
    const std::filesystem::path folder = first.parent_path();
    if (!folder.empty() && !std::filesystem::exists(folder)) {
        io::checkOutputFolder(folder.string(), option);
        std::filesystem::create_directory(folder);
    }
    io::checkOutputPath(first.string(), extensions, option);
}

Scene FrameSequence::sweptScene(int frame) const {
    if (!path_.sweep) return base_.scene();
    io::EditableScene edited = base_;
    const double value = path_.sweep->values.at(frame);
    try {
        edited.apply(io::SceneEdit{path_.sweep->field, Json::Value(value)});
        return edited.scene();
    } catch (const std::invalid_argument& e) {  // a malformed field path
        throw std::invalid_argument("--sweep " + path_.sweep->field + ": " + e.what());
    } catch (const io::InputError& e) {  // the swept value, not the file as written, is refused: say so
        throw io::InputError(
            e.file(), e.line(), e.field(),
            "the sweep sets " + path_.sweep->field + " = " + input::significantDigits(value, 12) + ": " + e.reason(),
            "");
    }
}

void FrameSequence::moveObserver(Scene& scene, int frame) const {
    if (!path_.properTime) return;
    ObserverEvent event;
    if (!worldLine_.empty()) {
        event = worldLine_[static_cast<std::size_t>(frame)];
    } else {  // the sweep changes the spacetime or the observer: its world line is this frame's own
        event = observerWorldLine(*scene.spacetime, scene.observer, scene.observerVelocity,
                                  path_.motion.value_or(defaultObserverMotion(scene.observerVelocity)),
                                  {path_.properTime->at(frame)}, worldLineAccuracy())
                    .front();
    }
    scene.observer = event.position;
    scene.observerVelocity = event.velocity;
}

Scene FrameSequence::scene(int frame) const {
    if (frame < 0 || frame >= frames_)
        throw std::out_of_range("frame " + std::to_string(frame) + " of " + std::to_string(frames_));
    Scene s = sweptScene(frame);
    moveObserver(s, frame);
    if (path_.orbitDegrees) orbit(s, path_.orbitDegrees->at(frame));
    if (path_.panDegrees) pan(s, path_.panDegrees->at(frame));
    if (adjust_) adjust_(s);
    try {
        s.camera.validate();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("frame " + std::to_string(frame) + ": " + e.what());
    }
    return s;
}

}  // namespace lc::cli
