// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene file with in-place edits, as the GUI's properties dock and session files hold it. An
// edit sets one field of the scene's JSON document ("metric.a", "objects[0].centre",
// "camera.fov"); the edited document goes through the scene reader itself, so an edit is
// accepted or refused by exactly the rules (and with the words) of a scene file.
#include "readers/io/scene_reader.hpp"

#include <json/json.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lc::io {

struct SceneEdit {
    std::string field;  // dotted path with [i] for array elements, as the reader names fields
    Json::Value value;  // null: remove the field (the reader's default applies)
};

class EditableScene {
public:
    // Throws InputError (file:line:field) when the file is not a valid scene.
    static EditableScene load(const std::string& file, const SceneReadOptions& options = {});
    // A document held elsewhere (a session's copy); `baseDir` resolves texture and mesh paths.
    // `editsInDocument`: the edits that made the copy from its scene file; edits() keeps them
    // ahead of new ones, so a session saved again still replays to this document once the scene
    // file is back.
    static EditableScene fromDocument(const Json::Value& document, const std::string& nameForMessages,
                                      const std::string& baseDir, const SceneReadOptions& options = {},
                                      std::vector<SceneEdit> editsInDocument = {});

    const Scene& scene() const { return scene_; }
    const Json::Value& document() const { return edited_; }  // with every edit applied
    // The scene as read, before any edit: parsed from a compact copy of its text when first asked
    // for (a second document of a 40 MB scene held 150 MB; fields are asked by originalValue).
    const Json::Value& original() const;
    // The edits that replay the scene file to document(), in order (see fromDocument).
    std::vector<SceneEdit> edits() const;
    const std::string& source() const { return source_; }
    const std::string& baseDir() const { return baseDir_; }

    // The field's value in the edited document; null when the file does not give it.
    Json::Value value(const std::string& field) const;
    // The edit that undoes an edit of `field` now: the field's value, or, where the edit would
    // create the field or members above it, the removal of the highest one it creates.
    SceneEdit undoing(const std::string& field) const;
    // The field's value in the scene file (before any edit); null when the file does not give it.
    Json::Value originalValue(const std::string& field) const;
    // The accepted range of a number field the reader checked in the edited document (the
    // properties' tooltips); nullptr for fields that are not numbers or that the file leaves out.
    const input::Range* rangeOf(const std::string& field) const;
    std::size_t checkedRangeCount() const { return ranges_.size(); }  // kinds of field checked
    // Sets the field and re-reads the scene. Refused edits throw InputError whose reason() is the
    // reader's and whose field() is the edited field; the scene and edits are then unchanged. An
    // edit back to the file's own value drops the field from edits().
    void apply(const SceneEdit& edit);
    // Several fields at once, read once (e.g. projection and field of view together, where either
    // alone is refused); all or nothing.
    void apply(const std::vector<SceneEdit>& edits);

private:
    static Scene read(const Json::Value& document, const std::string& name, const std::string& baseDir,
                      const SceneReadOptions& options, std::map<std::string, input::Range>& ranges);
    void setField(Json::Value& document, const SceneEdit& edit) const;
    void parseOriginal(Json::Value& document) const;
    // `fileValue`: the field's value in the scene as read (null where it has none).
    void record(const SceneEdit& edit, const Json::Value& fileValue);

    Json::Value edited_;
    std::string originalText_;                                     // the scene as read, compact JSON
    mutable std::shared_ptr<const Json::Value> originalDocument_;  // parsed from it when asked for
    std::map<std::string, Json::Value> fileValues_;                // each edit's field as the scene had it
    std::vector<SceneEdit> inherited_, edits_;
    std::string source_, baseDir_;
    SceneReadOptions options_;
    Scene scene_;
    std::map<std::string, input::Range> ranges_;  // of edited_, as the reader checked them
};

// Field paths: "a.b[2].c" -> the value it names inside `root`; throws std::invalid_argument when
// the path is malformed, indexes past an array's end or walks into a number. `create` adds
// missing object members (for setting), otherwise a missing member yields null.
Json::Value* fieldOf(Json::Value& root, const std::string& field, bool create);

}  // namespace lc::io
