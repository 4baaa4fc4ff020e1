// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/json_document.hpp"

#include "readers/io/input_file.hpp"
#include "readers/io/install_layout.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <filesystem>

namespace lc::io {

InputError::InputError(const std::string& file, int line, const std::string& field, const std::string& problem,
                       const std::string& hint)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                         (field.empty() ? "" : "field '" + field + "': ") + problem +
                         (hint.empty() ? "" : " (hint: " + hint + ")")),
      file_(file),
      field_(field),
      reason_(problem + (hint.empty() ? "" : " (hint: " + hint + ")")),
      line_(line) {}

namespace {

// `missingHint`: what to say instead of "check the path and permissions" when the file is absent.
std::string readJsonFile(const std::string& file, const std::string& missingHint) {
    try {
        return readInputFile(file, input::kSceneFileBytes);
    } catch (const std::exception& e) {
        std::error_code ignored;
        const bool missing = !missingHint.empty() && !std::filesystem::exists(file, ignored);
        throw InputError(file, 0, "", std::string("the file ") + e.what(),
                         missing ? missingHint : "check the path and permissions");
    }
}

}  // namespace

std::shared_ptr<JsonDocument> JsonDocument::load(const std::string& file) {
    return parse(readJsonFile(file, ""), file);
}

std::shared_ptr<JsonDocument> JsonDocument::loadDataFile(const std::string& given, bool metricFile) {
    std::string searched;
    const std::string file = findDataFile(given, metricFile, &searched);
    return parse(readJsonFile(file, searched), file);
}

std::shared_ptr<JsonDocument> JsonDocument::parse(const std::string& text, const std::string& name) {
    auto doc = std::make_shared<JsonDocument>();
    doc->file_ = name;
    doc->text_ = text;
    Json::CharReaderBuilder builder;
    builder["collectComments"] = false;
    builder["rejectDupKeys"] = true;
    builder["failIfExtra"] = true;  // a second document or trailing text is an error, not ignored
    std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
    std::string errors;
    bool parsed = false;
    try {
        parsed = reader->parse(doc->text_.data(), doc->text_.data() + doc->text_.size(), &doc->root_, &errors);
    } catch (const std::exception& e) {  // jsoncpp throws past its nesting limit (1000 levels)
        throw InputError(name, 0, "", std::string("invalid JSON: ") + e.what(), "nest arrays and objects less deeply");
    }
    if (!parsed) {
        // jsoncpp reports "* Line L, Column C\n  message"; keep its first line number.
        std::smatch m;
        int line = 0;
        if (std::regex_search(errors, m, std::regex("Line (\\d+)"))) line = std::stoi(m[1]);
        std::string msg = errors;
        msg.erase(std::remove(msg.begin(), msg.end(), '\n'), msg.end());
        throw InputError(name, line, "", "invalid JSON: " + msg, "check commas, quotes and brackets near that line");
    }
    return doc;
}

std::shared_ptr<JsonDocument> JsonDocument::view(const Json::Value& root, const std::string& name) {
    auto doc = std::make_shared<JsonDocument>();
    doc->file_ = name;
    doc->rootOf_ = &root;
    return doc;
}

JsonNode JsonDocument::root() const { return JsonNode(shared_from_this(), rootOf_, ""); }

int JsonDocument::lineOf(const Json::Value& v) const {
    const auto off = static_cast<std::size_t>(std::min<std::ptrdiff_t>(v.getOffsetStart(), text_.size()));
    return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(off), '\n'));
}

JsonNode::JsonNode(std::shared_ptr<const JsonDocument> doc, const Json::Value* value, std::string path)
    : doc_(std::move(doc)), value_(value), path_(std::move(path)) {}

int JsonNode::line() const { return doc_->lineOf(*value_); }

void JsonNode::fail(const std::string& problem, const std::string& hint) const {
    throw InputError(doc_->file(), line(), path_, problem, hint);
}

bool JsonNode::has(const std::string& key) const { return value_->isObject() && value_->isMember(key); }

std::vector<std::string> JsonNode::keys() const {
    if (!value_->isObject()) fail("expected an object");
    return value_->getMemberNames();
}

JsonNode JsonNode::at(const std::string& key) const {
    if (!value_->isObject()) fail("expected an object with member '" + key + "'");
    const std::string p = path_.empty() ? key : path_ + "." + key;
    if (!value_->isMember(key))
        fail("missing required field '" + key + "'",
             "add \"" + key + "\": ... to " + (path_.empty() ? "the top level" : "'" + path_ + "'"));
    return JsonNode(doc_, &(*value_)[key], p);
}

JsonNode JsonNode::operator[](std::size_t i) const {
    if (i >= size()) fail("expected an array of at least " + std::to_string(i + 1) + " elements");
    return JsonNode(doc_, &(*value_)[static_cast<Json::ArrayIndex>(i)], path_ + "[" + std::to_string(i) + "]");
}

std::size_t JsonNode::size() const {
    if (!value_->isArray()) fail("expected an array");
    return value_->size();
}

std::size_t JsonNode::size(std::size_t min, std::size_t max) const {
    const std::size_t n = size();
    if (n < min || n > max)
        fail("expected an array of " + std::to_string(min) + " to " + std::to_string(max) + " elements, got " +
             std::to_string(n));
    return n;
}

std::string JsonDocument::rangeKey(const std::string& path, bool trailingToo) {
    std::string key;
    key.reserve(path.size());
    for (std::size_t k = 0; k < path.size(); ++k) {
        key += path[k];
        if (path[k] != '[') continue;
        const std::size_t close = path.find(']', k);
        if (close == std::string::npos || (close + 1 == path.size() && !trailingToo))
            continue;  // a trailing index stays
        k = close - 1;
    }
    return key;
}

double JsonNode::number() const {
    if (!value_->isNumeric() || value_->isBool())
        fail("expected a number, got " + value_->toStyledString().substr(0, 40));
    const double v = value_->asDouble();
    if (!std::isfinite(v)) fail("expected a finite number");
    return v;
}

double JsonNode::number(const input::Range& range) const {
    if (!value_->isNumeric() || value_->isBool())
        fail("expected a number, got " + value_->toStyledString().substr(0, 40));
    const double v = value_->asDouble();
    doc_->noteRange(path_, range);
    if (!range.contains(v)) fail(range.problem(v), range.why);
    return v;
}

int JsonNode::integer(const input::Range& range) const {
    return static_cast<int>(number(range));  // ranges of integers fit an int
}

double JsonNode::positive() const {
    const double v = number();
    if (!(v > 0)) fail("expected a number > 0, got " + std::to_string(v));
    return v;
}

std::string JsonNode::string() const {
    if (!value_->isString()) fail("expected a string");
    return value_->asString();
}

bool JsonNode::boolean() const {
    if (!value_->isBool()) fail("expected true or false");
    return value_->asBool();
}

std::vector<double> JsonNode::numbers(std::size_t n) const {
    if (!value_->isArray() || value_->size() != n)
        fail("expected an array of " + std::to_string(n) + " numbers", "e.g. [" +
                                                                           std::string(n == 4   ? "t, x, y, z"
                                                                                       : n == 3 ? "x, y, z"
                                                                                                : "...") +
                                                                           "]");
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back((*this)[i].number());
    return out;
}

std::vector<double> JsonNode::numbers(std::size_t n, const input::Range& range) const {
    numbers(n);  // shape first: array of n numbers
    doc_->noteListRange(path_, range);
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back((*this)[i].number(range));
    return out;
}

double JsonNode::number(const std::string& key, double fallback) const {
    return has(key) ? at(key).number() : fallback;
}

std::string JsonNode::string(const std::string& key, const std::string& fallback) const {
    return has(key) ? at(key).string() : fallback;
}

void JsonNode::allowOnly(const std::vector<std::string>& known) const {
    if (!value_->isObject()) fail("expected an object");
    for (const auto& name : value_->getMemberNames()) {
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        JsonNode(doc_, &(*value_)[name], path_.empty() ? name : path_ + "." + name)
            .fail("unknown field", "known fields here: " + list);
    }
}

}  // namespace lc::io
