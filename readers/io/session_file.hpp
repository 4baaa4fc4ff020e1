// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Session files (docs/SESSIONS.md): the scene by path plus its in-place edits, a copy of the
// edited scene for when the file has moved, the view state and the window layout, so that
// reopening a session reproduces the same image pixel for pixel. The GUI saves and opens them;
// `lightcone render --session` renders them. Errors name the session file, line and field.
#include "readers/io/scene_edits.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace lc::io {

// The GUI's post-rendering dock as a session keeps it (docs/SESSIONS.md, view.post_render):
// the same image again once the per-pixel data is traced, and in File > Export image.
struct PostRenderControls {
    bool enabled = false;
    std::string texture = "scene";      // "scene", "checker" or "stripes"
    double uOffset = 0;                 // turns, [0, 1]
    int repeats = 1;                    // texture repeats in u and v, [1, 8]
    std::optional<double> temperature;  // K, [1000, 30000]: every object a black body
    // Start and width as fractions of the rendered objects' emission times, each in [0, 1].
    std::optional<std::array<double, 2>> timeWindow;
    std::string outside = "background";  // outside the window: "background", "checker", "stripes"
    std::optional<double> blinkPhase;    // blinking from this fraction of a period, [0, 1]
    bool operator==(const PostRenderControls& o) const;
};

struct SessionFile {
    // Version 2: the camera's forward and up are chart directions (docs/SCENES.md). Version 1 gave
    // them as components in the observer's Gram-Schmidt frame; opening one converts them (same image).
    static constexpr int kVersion = 2;
    int version = kVersion;     // as read
    std::string scenePath;      // relative to the session file's folder, or absolute
    Json::Value sceneDocument;  // the edited scene, opened when scenePath cannot be read
    std::vector<SceneEdit> edits;
    std::vector<int> editLines;      // line of each edit in the file read (for messages; not written)
    int pickedI = -1, pickedJ = -1;  // the picked pixel (-1: none)
    int selectedObject = -1;         // the object of the images table (-1: none)
    bool imageFromShaders = true;    // the egocentric image from the shader renderers where they draw the scene
    PostRenderControls postRender;
    std::string windowState, windowGeometry;  // base64 (QMainWindow::saveState / saveGeometry)
    // The undo history up to where the user stood, oldest first (the redo tail is not kept): each
    // step's text and the fields it set, with their values before (null: the field was absent).
    // The GUI opens it as undoable steps; the scene itself comes from the edits above.
    struct HistoryStep {
        std::string text;
        std::vector<SceneEdit> after, before;
    };
    std::vector<HistoryStep> history;
    // The spacetime view's 3D camera: position, focal point, view up (3 each), view angle (deg);
    // empty: fitted to the scene.
    std::vector<double> spacetimeCamera;
};

SessionFile readSession(const std::string& file);
SessionFile parseSession(const std::string& text, const std::string& nameForMessages);
SessionFile sessionFromDocument(const JsonDocument& doc);
std::string sessionText(const SessionFile& session);
// All or nothing (io::writeFileAtomically): an old session is never half overwritten.
void writeSession(const std::string& file, const SessionFile& session);

// The session's scene: the file at scenePath with the edits applied or, when that file cannot be
// read, the saved copy (a notice says so). Edits the scene reader refuses throw InputError naming
// the session file, the edit's line and the reason.
struct OpenedSession {
    EditableScene scene;
    std::string notice;  // empty, or why the saved copy was used
};
OpenedSession openSessionScene(const SessionFile& session, const std::string& sessionFile,
                               const SceneReadOptions& options = {});

// scenePath for a session saved at `sessionFile`: relative to its folder when both are in one tree.
std::string scenePathForSession(const std::string& sceneFile, const std::string& sessionFile);

}  // namespace lc::io
