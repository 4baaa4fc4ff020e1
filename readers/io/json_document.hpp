// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A parsed JSON file whose every value knows its path and line, so that errors name the file,
// the line, the field and what was expected. Unknown fields are errors, not silently ignored.
#include "core/input/ranges.hpp"
#include "core/numerics/types.hpp"

#include <json/json.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::io {

class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, int line, const std::string& field, const std::string& problem,
               const std::string& hint);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& field() const { return field_; }
    // The problem and hint without file, line and field: what a GUI shows next to the field.
    const std::string& reason() const { return reason_; }

private:
    std::string file_, field_, reason_;
    int line_;
};

class JsonDocument;

// One value inside a document: a view (cheap to copy) that reports errors in context.
class JsonNode {
public:
    JsonNode(std::shared_ptr<const JsonDocument> doc, const Json::Value* value, std::string path);

    const std::string& path() const { return path_; }
    int line() const;
    bool isObject() const { return value_->isObject(); }
    bool isArray() const { return value_->isArray(); }
    bool isString() const { return value_->isString(); }

    bool has(const std::string& key) const;
    std::vector<std::string> keys() const;                     // an object's member names (fails unless an object)
    JsonNode at(const std::string& key) const;                 // required member
    JsonNode operator[](std::size_t i) const;                  // array element (fails unless an array this long)
    std::size_t size() const;                                  // array length (fails unless an array)
    std::size_t size(std::size_t min, std::size_t max) const;  // array length, bounded

    double number() const;                           // any finite number
    double number(const input::Range& range) const;  // finite and inside the documented range
    int integer(const input::Range& range) const;
    double positive() const;  // > 0
    std::string string() const;
    bool boolean() const;                                          // true or false
    std::vector<double> numbers(std::size_t expectedCount) const;  // fixed-size numeric array
    std::vector<double> numbers(std::size_t expectedCount, const input::Range& eachInRange) const;

    // Optional members with defaults.
    double number(const std::string& key, double fallback) const;
    std::string string(const std::string& key, const std::string& fallback) const;

    // Every member must be one of `known`; the error lists them.
    void allowOnly(const std::vector<std::string>& known) const;

    [[noreturn]] void fail(const std::string& problem, const std::string& hint = "") const;

private:
    std::shared_ptr<const JsonDocument> doc_;
    const Json::Value* value_;
    std::string path_;
};

class JsonDocument : public std::enable_shared_from_this<JsonDocument> {
public:
    // Throws InputError for unreadable files, files that are not regular or over
    // input::kSceneFileBytes, and syntax errors (with line and column). Strict: one document,
    // nothing after it, no duplicate keys.
    static std::shared_ptr<JsonDocument> load(const std::string& file);
    // A scene or metric file as users name it: `given` itself, or a bare name found in the data
    // search path (io/install_layout's findDataFile); file() is the file read. A file found
    // nowhere is refused saying where it was looked for.
    static std::shared_ptr<JsonDocument> loadDataFile(const std::string& given, bool metricFile);
    static std::shared_ptr<JsonDocument> parse(const std::string& text, const std::string& nameForMessages);
    // A document already in memory (an edited scene), read where it is: no text, so no lines in
    // messages. `root` must outlive the document and every node taken from it.
    static std::shared_ptr<JsonDocument> view(const Json::Value& root, const std::string& nameForMessages);
    JsonNode root() const;
    const Json::Value& rootValue() const { return *rootOf_; }
    const std::string& file() const { return file_; }
    int lineOf(const Json::Value& v) const;

    // The accepted range of every number read so far through JsonNode::number(range),
    // integer(range) or numbers(n, range), by rangeKey of its field path ("objects[].radius",
    // "camera.fov[1]"): what a GUI shows beside a field, from the check itself. One entry per kind
    // of field, not per number: a 40 MB scene's 2 million numbers once took 280 MB here.
    const std::map<std::string, input::Range>& checkedRanges() const { return ranges_; }
    void noteRange(const std::string& path, const input::Range& range) const {
        ranges_.insert_or_assign(rangeKey(path), range);
    }
    // A list of numbers read at once (an event, a colour): every index left out, the list's own
    // too (a world line's million events share one entry).
    void noteListRange(const std::string& path, const input::Range& range) const {
        ranges_.insert_or_assign(rangeKey(path, true), range);
    }
    // The path with every index but a trailing one left out: "objects[3].motion.points[7][2]" ->
    // "objects[].motion.points[][2]" (the elements of a list share their fields' ranges); with
    // `trailingToo`, that one as well.
    static std::string rangeKey(const std::string& path, bool trailingToo = false);

private:
    std::string file_, text_;
    Json::Value root_;
    const Json::Value* rootOf_ = &root_;                  // root_, or a viewed document
    mutable std::map<std::string, input::Range> ranges_;  // a log of the reads, not the document
};

// A point or vector's four components as a JSON array, the form scene files and reports use.
inline Json::Value jsonArray(const Vec4& v) {
    Json::Value array(Json::arrayValue);
    for (int k = 0; k < 4; ++k) array.append(v(k));
    return array;
}

}  // namespace lc::io
