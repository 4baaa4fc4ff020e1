// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/session_file.hpp"

#include "readers/io/atomic_output.hpp"
#include "readers/io/provenance.hpp"
#include "core/scene/frame_camera.hpp"

#include <filesystem>

namespace lc::io {
namespace fs = std::filesystem;
namespace {

const input::Range kPixelIndex{"session picked pixel", -1, 16384, true, "px", "an image side is at most 16384 px"};
const input::Range kObjectIndex{"session selected object", -1, 1000, true, "", "a scene has at most 1000 objects"};
const input::Range kFraction{
    "session post-render fraction", 0, 1, false, "", "a fraction of a turn or of the emission times"};
const input::Range kRepeats{"session post-render repeats", 1, 8, true, "", "the dock's slider offers 1 to 8 repeats"};
const input::Range kShadeTemperature{"session post-render temperature",        1000, 30000, false, "K",
                                     "the dock's slider spans 1000 to 30000 K"};
const char* const kTextures[] = {"scene", "checker", "stripes"};
const char* const kOutside[] = {"background", "checker", "stripes"};
constexpr std::size_t kMaxLayoutText = 1 << 16;  // Qt's saved layouts are a few kB
constexpr std::size_t kMaxEdits = 10000;
constexpr std::size_t kMaxStepText = 200, kMaxStepFields = 64;
const input::Range kCameraNumber{"session spacetime camera",
                                 -1e12,
                                 1e12,
                                 false,
                                 "chart units, degrees",
                                 "a 3D view's camera: position, focal point, view up, view angle"};

std::string base64(const JsonNode& n) {
    const std::string s = n.string();
    if (s.size() > kMaxLayoutText)
        n.fail("longer than " + std::to_string(kMaxLayoutText) + " characters", "the GUI writes a few kB here");
    if (s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=") != std::string::npos)
        n.fail("not base64 text", "the GUI writes this; delete the field to use the default layout");
    return s;
}

// A list of {"field", "value"} (value any JSON, required: null removes the field), `raw` its JSON
// value; each edit's line into `lines` where given.
std::vector<SceneEdit> readEdits(const JsonNode& list, const Json::Value& raw, std::size_t least, std::size_t most,
                                 std::vector<int>* lines = nullptr) {
    std::vector<SceneEdit> edits;
    const std::size_t n = list.size(least, most);
    for (std::size_t k = 0; k < n; ++k) {
        const JsonNode e = list[k];
        e.allowOnly({"field", "value"});
        SceneEdit edit;
        edit.field = e.at("field").string();
        e.at("value");
        edit.value = raw[static_cast<Json::ArrayIndex>(k)]["value"];
        edits.push_back(std::move(edit));
        if (lines) lines->push_back(e.line());
    }
    return edits;
}

// A version-1 session gave the camera's forward and up as components in the observer's frame:
// the chart directions that the frame sees there replace them, so the session keeps its image.
void convertVersion1Camera(OpenedSession& out, const std::string& sessionFile) {
    const Scene& scene = out.scene.scene();
    const LocalFrame frame = observerFrame(scene);
    auto chart = [&](const Vec3& frameComponents) {
        const Vec3 v = chartVectorOf(*scene.spacetime, frame, frameComponents.normalized());
        Json::Value a(Json::arrayValue);
        for (int k = 0; k < 3; ++k) a.append(v(k));
        return a;
    };
    const Camera& cam = scene.camera;
    const Camera now = frameCamera(scene);  // what the numbers would mean as chart directions
    const bool same = (now.forward.normalized() - cam.forward.normalized()).norm() < 1e-12 &&
                      (now.up.normalized() - cam.up.normalized()).norm() < 1e-12;
    if (same) return;  // the frame is the chart's there (e.g. the Goedel axis): nothing to convert
    out.scene.apply(std::vector<SceneEdit>{{"camera.forward", chart(cam.forward)}, {"camera.up", chart(cam.up)}});
    const std::string note = sessionFile +
                             " is a version-1 session: its camera forward and up were frame "
                             "components, now converted to chart directions (the same image)";
    out.notice = out.notice.empty() ? note : out.notice + "; " + note;
}

template <std::size_t N>
std::string choice(const JsonNode& n, const char* const (&words)[N]) {
    const std::string s = n.string();
    std::string list;
    for (const char* w : words) {
        if (s == w) return s;
        list += std::string(list.empty() ? "" : ", ") + w;
    }
    n.fail("'" + s + "' is not one of " + list, "the post-rendering dock's choices");
    return s;
}

PostRenderControls readPostRender(const JsonNode& p) {
    p.allowOnly({"texture", "u_offset", "repeats", "temperature", "time_window", "outside", "blink_phase"});
    PostRenderControls c;
    c.enabled = true;
    if (p.has("texture")) c.texture = choice(p.at("texture"), kTextures);
    if (p.has("u_offset")) c.uOffset = p.at("u_offset").number(kFraction);
    if (p.has("repeats")) c.repeats = p.at("repeats").integer(kRepeats);
    if (p.has("temperature")) c.temperature = p.at("temperature").number(kShadeTemperature);
    if (p.has("time_window")) {
        const auto w = p.at("time_window").numbers(2, kFraction);
        c.timeWindow = std::array<double, 2>{w[0], w[1]};
    }
    if (p.has("outside")) c.outside = choice(p.at("outside"), kOutside);
    if (p.has("blink_phase")) c.blinkPhase = p.at("blink_phase").number(kFraction);
    return c;
}

Json::Value postRenderValue(const PostRenderControls& c) {
    Json::Value p(Json::objectValue);
    p["texture"] = c.texture;
    p["u_offset"] = c.uOffset;
    p["repeats"] = c.repeats;
    if (c.temperature) p["temperature"] = *c.temperature;
    if (c.timeWindow) {
        p["time_window"].append((*c.timeWindow)[0]);
        p["time_window"].append((*c.timeWindow)[1]);
        p["outside"] = c.outside;
    }
    if (c.blinkPhase) p["blink_phase"] = *c.blinkPhase;
    return p;
}

fs::path sceneFileOf(const SessionFile& s, const std::string& sessionFile) {
    const fs::path p(s.scenePath);
    return p.is_absolute() ? p : fs::path(sessionFile).parent_path() / p;
}

}  // namespace

bool PostRenderControls::operator==(const PostRenderControls& o) const {
    return enabled == o.enabled && texture == o.texture && uOffset == o.uOffset && repeats == o.repeats &&
           temperature == o.temperature && timeWindow == o.timeWindow && outside == o.outside &&
           blinkPhase == o.blinkPhase;
}

SessionFile readSession(const std::string& file) { return sessionFromDocument(*JsonDocument::load(file)); }

SessionFile parseSession(const std::string& text, const std::string& nameForMessages) {
    return sessionFromDocument(*JsonDocument::parse(text, nameForMessages));
}

SessionFile sessionFromDocument(const JsonDocument& docRef) {
    const JsonDocument* doc = &docRef;
    const JsonNode root = doc->root();
    if (!root.isObject()) root.fail("a session is a JSON object", "see docs/SESSIONS.md");
    root.allowOnly({"lightcone_session", "written_by", "scene", "view", "window"});
    const JsonNode version = root.at("lightcone_session");
    const input::Range versions{"session version", 1, SessionFile::kVersion, true, "", "versions this program reads"};
    SessionFile s;
    s.version = version.integer(versions);
    const Json::Value& raw = doc->rootValue();

    const JsonNode scene = root.at("scene");
    scene.allowOnly({"path", "edits", "document", "history"});
    s.scenePath = scene.at("path").string();
    if (s.scenePath.empty()) scene.at("path").fail("an empty path", "the scene file this session edits");
    if (scene.has("document")) {
        const JsonNode d = scene.at("document");
        if (!d.isObject()) d.fail("expected the scene as a JSON object", "the GUI saves the edited scene here");
        s.sceneDocument = raw["scene"]["document"];
    }
    if (scene.has("edits")) s.edits = readEdits(scene.at("edits"), raw["scene"]["edits"], 0, kMaxEdits, &s.editLines);
    if (scene.has("history")) {
        const JsonNode history = scene.at("history");
        const std::size_t n = history.size(0, kMaxEdits);
        for (std::size_t k = 0; k < n; ++k) {
            const JsonNode step = history[k];
            step.allowOnly({"text", "after", "before"});
            SessionFile::HistoryStep h;
            h.text = step.at("text").string();
            if (h.text.size() > kMaxStepText)
                step.at("text").fail("longer than " + std::to_string(kMaxStepText) + " characters",
                                     "the GUI writes an undo step's short description here");
            const Json::Value& rawStep = raw["scene"]["history"][static_cast<Json::ArrayIndex>(k)];
            h.after = readEdits(step.at("after"), rawStep["after"], 1, kMaxStepFields);
            h.before = readEdits(step.at("before"), rawStep["before"], 1, kMaxStepFields);
            if (h.after.size() != h.before.size())
                step.fail("'after' and 'before' name " + std::to_string(h.after.size()) + " and " +
                              std::to_string(h.before.size()) + " fields",
                          "each field a step set, with its value before");
            s.history.push_back(std::move(h));
        }
    }
    if (root.has("view")) {
        const JsonNode v = root.at("view");
        v.allowOnly({"picked_pixel", "selected_object", "image_from_shaders", "post_render", "spacetime_camera"});
        if (v.has("spacetime_camera")) s.spacetimeCamera = v.at("spacetime_camera").numbers(10, kCameraNumber);
        if (v.has("post_render")) s.postRender = readPostRender(v.at("post_render"));
        if (v.has("image_from_shaders")) {
            const JsonNode b = v.at("image_from_shaders");
            if (!raw["view"]["image_from_shaders"].isBool())
                b.fail("expected true or false", "false: the CPU renderer draws the image");
            s.imageFromShaders = raw["view"]["image_from_shaders"].asBool();
        }
        if (v.has("picked_pixel")) {
            const auto ij = v.at("picked_pixel").numbers(2, kPixelIndex);
            s.pickedI = static_cast<int>(ij[0]);
            s.pickedJ = static_cast<int>(ij[1]);
        }
        if (v.has("selected_object")) s.selectedObject = v.at("selected_object").integer(kObjectIndex);
    }
    if (root.has("window")) {
        const JsonNode w = root.at("window");
        w.allowOnly({"state", "geometry"});
        if (w.has("state")) s.windowState = base64(w.at("state"));
        if (w.has("geometry")) s.windowGeometry = base64(w.at("geometry"));
    }
    return s;
}

std::string sessionText(const SessionFile& s) {
    Json::Value root(Json::objectValue);
    root["lightcone_session"] = SessionFile::kVersion;
    root["written_by"] = softwareName();  // read past: provenance only (io/provenance)
    Json::Value& scene = root["scene"];
    scene["path"] = s.scenePath;
    scene["edits"] = Json::Value(Json::arrayValue);
    for (const auto& e : s.edits) {
        Json::Value edit(Json::objectValue);
        edit["field"] = e.field;
        edit["value"] = e.value;
        scene["edits"].append(edit);
    }
    if (s.sceneDocument.isObject()) scene["document"] = s.sceneDocument;
    if (!s.history.empty()) {
        Json::Value& history = scene["history"];
        history = Json::Value(Json::arrayValue);
        for (const auto& h : s.history) {
            Json::Value step(Json::objectValue);
            step["text"] = h.text;
            for (const auto& [side, edits] : {std::pair{"after", &h.after}, std::pair{"before", &h.before}}) {
                step[side] = Json::Value(Json::arrayValue);
                for (const auto& e : *edits) {
                    Json::Value edit(Json::objectValue);
                    edit["field"] = e.field;
                    edit["value"] = e.value;
                    step[side].append(edit);
                }
            }
            history.append(step);
        }
    }
    Json::Value& view = root["view"];
    view = Json::Value(Json::objectValue);
    if (s.pickedI >= 0 && s.pickedJ >= 0) {
        view["picked_pixel"].append(s.pickedI);
        view["picked_pixel"].append(s.pickedJ);
    }
    if (s.selectedObject >= 0) view["selected_object"] = s.selectedObject;
    view["image_from_shaders"] = s.imageFromShaders;
    if (s.postRender.enabled) view["post_render"] = postRenderValue(s.postRender);
    if (s.spacetimeCamera.size() == 10)
        for (double v : s.spacetimeCamera) view["spacetime_camera"].append(v);
    if (!s.windowState.empty() || !s.windowGeometry.empty()) {
        root["window"]["state"] = s.windowState;
        root["window"]["geometry"] = s.windowGeometry;
    }
    Json::StreamWriterBuilder w;
    w["indentation"] = "  ";
    w["precision"] = 17;  // doubles round-trip exactly: the same scene, the same pixels
    return Json::writeString(w, root) + "\n";
}

void writeSession(const std::string& file, const SessionFile& session) {
    writeFileAtomically(file, sessionText(session), "session");
}

OpenedSession openSessionScene(const SessionFile& s, const std::string& sessionFile, const SceneReadOptions& options) {
    const fs::path sceneFile = sceneFileOf(s, sessionFile);
    std::error_code ec;
    OpenedSession out{EditableScene(), ""};
    if (!fs::is_regular_file(sceneFile, ec)) {
        if (!s.sceneDocument.isObject())
            throw InputError(sessionFile, 0, "scene.path", "the scene file " + sceneFile.string() + " is not there",
                             "move it back or give its new path in the session file");
        out.notice = "the scene file " + sceneFile.string() + " is not there; opened the copy saved in " + sessionFile;
        // Relative textures and meshes: beside the missing scene file if that folder is still
        // there, else beside the session.
        const fs::path folder = fs::is_directory(sceneFile.parent_path(), ec) ? sceneFile.parent_path()
                                                                              : fs::path(sessionFile).parent_path();
        out.scene = EditableScene::fromDocument(s.sceneDocument, sessionFile + " (saved scene)", folder.string(),
                                                options, s.edits);
        if (s.version < 2) convertVersion1Camera(out, sessionFile);
        return out;
    }
    out.scene = EditableScene::load(sceneFile.string(), options);
    // All edits at once, as the GUI made some of them together (projection and field of view:
    // either alone may be refused); on a refusal, the first edit that fails is named.
    EditableScene edited = out.scene;
    try {
        edited.apply(s.edits);
    } catch (const InputError& whole) {
        // The edit to name: bisection over prefixes, the first k edits accepted and the first k + 1
        // refused (log2 n trial reads; reading every prefix took minutes at 1e4 edits).
        std::size_t accepted = 0, refused = s.edits.size();
        InputError why = whole;
        while (refused - accepted > 1) {
            const std::size_t middle = accepted + (refused - accepted) / 2;
            EditableScene trial = out.scene;
            try {
                trial.apply(
                    std::vector<SceneEdit>(s.edits.begin(), s.edits.begin() + static_cast<std::ptrdiff_t>(middle)));
                accepted = middle;
            } catch (const InputError& e) {
                refused = middle;
                why = e;
            }
        }
        const std::size_t k = refused - 1;
        throw InputError(sessionFile, k < s.editLines.size() ? s.editLines[k] : 0,
                         "scene.edits[" + std::to_string(k) + "] (" + why.field() + ")", why.reason(),
                         "the scene file may have changed since the session was saved");
    }
    out.scene = std::move(edited);
    if (s.sceneDocument.isObject() && !(out.scene.document() == s.sceneDocument))
        out.notice = "the scene file " + sceneFile.string() + " changed since " + sessionFile +
                     " was saved: its edits were applied to the new file";
    if (s.version < 2) convertVersion1Camera(out, sessionFile);
    return out;
}

std::string scenePathForSession(const std::string& sceneFile, const std::string& sessionFile) {
    std::error_code ec;
    const fs::path scene = fs::weakly_canonical(fs::absolute(sceneFile), ec);
    const fs::path folder = fs::weakly_canonical(fs::absolute(sessionFile).parent_path(), ec);
    const fs::path rel = scene.lexically_relative(folder);
    if (!rel.empty() && rel.begin()->string() != "..") return rel.generic_string();
    if (!rel.empty()) {
        int ups = 0;
        for (const auto& part : rel) ups += part == "..";
        if (ups <= 3) return rel.generic_string();
    }
    return scene.string();
}

}  // namespace lc::io
