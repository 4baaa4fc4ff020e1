// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/scene_edits.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>

namespace lc::io {
namespace {

// The scene as read, kept as compact text (exact doubles) rather than as a second document.
std::string toText(const Json::Value& v) {
    Json::StreamWriterBuilder w;
    w["indentation"] = "";
    w["precision"] = 17;
    return Json::writeString(w, v);
}

// The value at `field` inside a document that is not to change: fieldOf without `create` only
// reads (members are looked up before they are indexed, elements are bounds-checked).
const Json::Value& readField(const Json::Value& root, const std::string& field) {
    return *fieldOf(const_cast<Json::Value&>(root), field, false);
}

// What an edit replaced, to put back when the reader refuses the edited document: the highest
// member the edit creates (removed again), or the value it overwrites. Taken before the edit,
// which may create members and then find its path malformed.
struct Replaced {
    std::string field;  // the path whose value is restored or removed; empty: nothing to put back
    bool existed = false;
    Json::Value value;
};

// Whether the document has the member or element a well-formed path names (a member holding
// null counts).
bool hasField(const Json::Value& document, const std::string& path) {
    if (path.back() == ']') return true;  // readField refused a missing element already
    const std::size_t dot = path.find_last_of('.');
    const Json::Value& parent = dot == std::string::npos ? document : readField(document, path.substr(0, dot));
    return parent.isObject() && parent.isMember(dot == std::string::npos ? path : path.substr(dot + 1));
}

// Drops the member a well-formed path ending in a name ("render.stepper") names from its parent;
// nothing where the document lacks it.
void dropMember(Json::Value& document, const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    Json::Value& parent = dot == std::string::npos ? document : *fieldOf(document, path.substr(0, dot), false);
    if (parent.isObject()) parent.removeMember(dot == std::string::npos ? path : path.substr(dot + 1));
}

Replaced replacedBy(const Json::Value& document, const std::string& field) {
    try {
        // The first prefix of the path ("render", then "render.stepper") the document lacks.
        for (std::size_t end = 1; end <= field.size(); ++end) {
            if (end < field.size() && field[end] != '.' && field[end] != '[') continue;
            const std::string prefix = field.substr(0, end);
            const Json::Value& at = readField(document, prefix);
            if (!hasField(document, prefix)) return {prefix, false, Json::Value()};
            if (end == field.size()) return {prefix, true, at};
        }
    } catch (const std::invalid_argument&) {
        // Malformed where every member before it exists: the edit refuses it before creating any.
    }
    return {};
}

// True when `inner` is `outer` itself or a part of it ("objects[0].radius" in "objects[0]").
bool nested(const std::string& inner, const std::string& outer) {
    if (outer.empty() || inner.compare(0, outer.size(), outer) != 0) return false;
    return inner.size() == outer.size() || inner[outer.size()] == '.' || inner[outer.size()] == '[';
}

// Scene fields nest a few levels (objects[0].motion.segments[2].speed); a path far deeper or
// longer is refused before any copying or creating, which a 1e5-level path once turned into a
// stack overflow.
constexpr std::size_t kMaxFieldLevels = 64, kMaxFieldLength = 1024;

// A field as messages show it: whole when short, else its start and its length.
std::string shownField(const std::string& field) {
    return field.size() <= 120 ? field : field.substr(0, 100) + "... (" + std::to_string(field.size()) + " characters)";
}

}  // namespace

Json::Value* fieldOf(Json::Value& root, const std::string& field, bool create) {
    if (field.empty()) throw std::invalid_argument("an empty field name");
    const auto levels = static_cast<std::size_t>(
                            std::count_if(field.begin(), field.end(), [](char c) { return c == '.' || c == '['; })) +
                        1;
    if (levels > kMaxFieldLevels || field.size() > kMaxFieldLength)
        throw std::invalid_argument("a field path of " + std::to_string(levels) + " levels and " +
                                    std::to_string(field.size()) + " characters: scene fields are at most " +
                                    std::to_string(kMaxFieldLevels) + " levels and " + std::to_string(kMaxFieldLength) +
                                    " characters long");
    // Every malformed path is named the same way (shortened when long).
    const auto malformed = [&field](const std::string& why) {
        return std::invalid_argument("field '" + shownField(field) + "': " + why);
    };
    static thread_local Json::Value absent;
    Json::Value* at = &root;
    std::size_t pos = 0;
    while (pos < field.size()) {
        if (field[pos] == '[') {
            const std::size_t close = field.find(']', pos);
            if (close == std::string::npos || close == pos + 1) throw malformed("'[' without an index and ']'");
            const std::string digits = field.substr(pos + 1, close - pos - 1);
            // One spelling per field (edits are matched by their text): no leading zeros.
            if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6 ||
                (digits.size() > 1 && digits[0] == '0'))
                throw malformed("'" + digits + "' is not an index");
            const auto index = static_cast<Json::ArrayIndex>(std::stoul(digits));
            if (!at->isArray() || index >= at->size())
                throw malformed("the scene has no element [" + digits + "] there");
            at = &(*at)[index];
            pos = close + 1;
            if (pos < field.size() && field[pos] != '.' && field[pos] != '[')
                throw malformed("'.' or '[' belongs after ']'");
            if (pos < field.size() && field[pos] == '.') {
                ++pos;
                if (pos == field.size()) throw malformed("ends with a '.'");
            }
            continue;
        }
        const std::size_t end = field.find_first_of(".[", pos);
        const std::string key = field.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
        if (key.empty()) throw malformed("an empty name between dots");
        if (!(at->isObject() || (create && at->isNull())))
            throw malformed("'" + key + "' is inside a value that has no fields");
        if (!create && !at->isMember(key)) {
            absent = Json::Value();
            return &absent;
        }
        at = &(*at)[key];
        pos = end == std::string::npos ? field.size() : (field[end] == '.' ? end + 1 : end);
        if (pos == field.size() && end != std::string::npos) throw malformed("ends with a '.'");
    }
    return at;
}

Scene EditableScene::read(const Json::Value& document, const std::string& name, const std::string& baseDir,
                          const SceneReadOptions& options, std::map<std::string, input::Range>& ranges) {
    // Read where it is: writing a 40 MB scene out and parsing it again took most of an edit.
    const auto doc = JsonDocument::view(document, name);
    Scene scene = sceneFromDocument(*doc, baseDir, options);
    ranges = doc->checkedRanges();
    return scene;
}

const input::Range* EditableScene::rangeOf(const std::string& field) const {
    auto found = ranges_.find(JsonDocument::rangeKey(field));
    if (found == ranges_.end()) found = ranges_.find(JsonDocument::rangeKey(field, true));  // a list read at once
    return found == ranges_.end() ? nullptr : &found->second;
}

EditableScene EditableScene::load(const std::string& given, const SceneReadOptions& options) {
    const auto doc = JsonDocument::loadDataFile(given, false);  // "kerr.json": the installed scenes
    const std::string& file = doc->file();
    EditableScene s;
    s.source_ = file;
    s.baseDir_ = std::filesystem::path(file).parent_path().string();
    if (s.baseDir_.empty()) s.baseDir_ = ".";
    s.options_ = options;
    s.scene_ = sceneFromDocument(*doc, s.baseDir_, options);  // messages with the file's own lines
    s.ranges_ = doc->checkedRanges();
    s.edited_ = doc->rootValue();
    s.originalText_ = toText(s.edited_);
    return s;
}

EditableScene EditableScene::fromDocument(const Json::Value& document, const std::string& name,
                                          const std::string& baseDir, const SceneReadOptions& options,
                                          std::vector<SceneEdit> editsInDocument) {
    EditableScene s;
    s.inherited_ = std::move(editsInDocument);
    s.source_ = name;
    s.baseDir_ = baseDir.empty() ? "." : baseDir;
    s.options_ = options;
    s.scene_ = read(document, name, s.baseDir_, options, s.ranges_);
    s.edited_ = document;
    s.originalText_ = toText(s.edited_);
    return s;
}

std::vector<SceneEdit> EditableScene::edits() const {
    std::vector<SceneEdit> all = inherited_;
    all.insert(all.end(), edits_.begin(), edits_.end());
    return all;
}

Json::Value EditableScene::value(const std::string& field) const { return readField(edited_, field); }

void EditableScene::parseOriginal(Json::Value& document) const {
    // Our own writer's text of a document the reader took: it parses.
    Json::CharReaderBuilder builder;
    const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
    std::string errors;
    if (!reader->parse(originalText_.data(), originalText_.data() + originalText_.size(), &document, &errors))
        throw std::logic_error("the scene's own text does not parse: " + errors);
}

SceneEdit EditableScene::undoing(const std::string& field) const {
    const Replaced replaced = replacedBy(edited_, field);
    if (replaced.field.empty()) return {field, Json::Value()};
    return {replaced.field, replaced.existed ? replaced.value : Json::Value()};
}

const Json::Value& EditableScene::original() const {
    if (!originalDocument_) {
        auto document = std::make_shared<Json::Value>();
        parseOriginal(*document);
        originalDocument_ = std::move(document);
    }
    return *originalDocument_;
}

Json::Value EditableScene::originalValue(const std::string& field) const {
    // A field no edit touches is as the scene had it; an edited one kept its file value; only a
    // field inside or around another edit needs the whole original document.
    bool exact = false, around = false;
    for (const SceneEdit& e : edits_) {
        if (e.field == field)
            exact = true;
        else if (nested(e.field, field) || nested(field, e.field))
            around = true;
    }
    if (!exact && !around) return readField(edited_, field);
    if (!around) {
        const auto kept = fileValues_.find(field);
        if (kept != fileValues_.end()) return kept->second;
    }
    if (originalDocument_) return readField(*originalDocument_, field);
    // Parsed for this field alone: kept, a 40 MB scene's second document would stay for the session.
    Json::Value document;
    parseOriginal(document);
    return readField(document, field);
}

void EditableScene::setField(Json::Value& document, const SceneEdit& edit) const {
    try {
        if (edit.field.empty()) throw std::invalid_argument("an empty field name");
        if (!edit.value.isNull()) {
            *fieldOf(document, edit.field, true) = edit.value;
            return;
        }
        // Removing: drop the member from its parent (a field the document lacks is removed already).
        if (edit.field.back() == ']')
            throw std::invalid_argument("field '" + edit.field + "': array elements cannot be removed");
        fieldOf(document, edit.field, false);  // checks the path
        dropMember(document, edit.field);
    } catch (const std::invalid_argument& e) {
        throw InputError(source_, 0, shownField(edit.field), e.what(),
                         "edit a field the scene has, or a member of an object");
    }
}

void EditableScene::apply(const SceneEdit& edit) { apply(std::vector<SceneEdit>{edit}); }

void EditableScene::apply(const std::vector<SceneEdit>& edits) {
    // Edited in place, what each edit replaced kept to be put back if the reader refuses: a copy
    // of the whole document cost a 40 MB scene seconds and a document's memory at every edit.
    std::vector<Replaced> replaced;
    const auto restore = [&] {
        for (auto r = replaced.rbegin(); r != replaced.rend(); ++r) {
            if (r->field.empty()) continue;
            if (r->existed) {
                *fieldOf(edited_, r->field, true) = r->value;  // a removed member comes back
                continue;
            }
            dropMember(edited_, r->field);
        }
    };
    // Each field's value in the scene as read, before the group changes any (record needs it).
    std::vector<Json::Value> fileValues;
    for (const auto& e : edits) {
        try {
            fileValues.push_back(originalValue(e.field));
        } catch (const std::invalid_argument&) {  // a malformed path: setField refuses it below
            fileValues.emplace_back();
        }
    }
    Scene scene;
    std::map<std::string, input::Range> ranges;
    try {
        for (const auto& e : edits) {
            replaced.push_back(replacedBy(edited_, e.field));
            setField(edited_, e);
        }
        scene = read(edited_, source_, baseDir_, options_, ranges);
    } catch (const InputError& e) {
        restore();
        // The reader's reason; the edited document has no lines of its own, so none is shown.
        const std::string field = !e.field().empty() ? e.field() : edits.empty() ? "" : edits.front().field;
        throw InputError(source_, 0, field, e.reason(), "");
    } catch (...) {
        restore();
        throw;
    }
    scene_ = std::move(scene);
    ranges_ = std::move(ranges);
    for (std::size_t k = 0; k < edits.size(); ++k) record(edits[k], fileValues[k]);
}

void EditableScene::record(const SceneEdit& edit, const Json::Value& fileValue) {
    // Replaying edits in this order must give the edited document: a changed edit moves to the
    // end, and one back at the file's value is dropped unless another edit touches that field.
    // The edit sets its whole field: earlier edits inside it (itself included) are superseded, and
    // kept they could name elements that only a later edit creates (a sphere added, its radius
    // edited, both undone: the radius edit would replay before the list that has the sphere).
    for (auto e = edits_.begin(); e != edits_.end();) {
        if (nested(e->field, edit.field)) {
            fileValues_.erase(e->field);
            e = edits_.erase(e);
        } else {
            ++e;
        }
    }
    const bool overlapsOthers = std::any_of(edits_.begin(), edits_.end(),
                                            [&](const SceneEdit& other) { return nested(edit.field, other.field); });
    if (!(edit.value == fileValue) || overlapsOthers) {
        edits_.push_back(edit);
        fileValues_[edit.field] = fileValue;
    } else {
        fileValues_.erase(edit.field);
    }
}

}  // namespace lc::io
