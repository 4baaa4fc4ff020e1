// SPDX-License-Identifier: BSD-3-Clause
// `--help`, `lightcone help`, docs/CLI.md and the bash completion, all from the declarations of
// app/cli/command_declarations.cpp. Each command's help is CLI11's, with a formatter that prints
// Lightcone's usage lines, each option's accepted range and choices, and the examples.
#include "app/cli/cli11_parser.hpp"
#include "app/cli/command_line.hpp"

#include <CLI/CLI.hpp>

#include <sstream>

namespace lc::cli {
namespace {

constexpr std::size_t kNameColumn = 30, kLineWidth = 110;

// `text` broken into lines of at most `width` characters at spaces.
std::string wrap(const std::string& text, std::size_t width) {
    std::istringstream words(text);
    std::string word, out, line;
    while (words >> word) {
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            out += line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
}

std::string joined(const std::vector<std::string>& words, const std::string& separator) {
    std::string s;
    for (const std::string& w : words) s += (s.empty() ? "" : separator) + w;
    return s;
}

class HelpFormatter : public CLI::Formatter {
public:
    explicit HelpFormatter(const CommandDeclaration& command) : command_(command) { column_width(kNameColumn); }

    std::string make_description(const CLI::App*) const override {
        return "lightcone " + command_.name + ": " + command_.summary + "\n\n";
    }

    std::string make_usage(const CLI::App*, std::string) const override {
        std::string out = "usage:\n";
        for (const std::string& line : command_.usage)
            out += "  lightcone " + command_.name + (line.empty() ? "" : " " + line) + "\n";
        return out;
    }

    std::string make_option_opts(const CLI::Option* option) const override {
        const OptionDeclaration* o = command_.option(option->get_name());
        return o && !o->flag() ? " " + o->value : "";
    }

    std::string make_option_desc(const CLI::Option* option) const override {
        const OptionDeclaration* o = command_.option(option->get_name());
        if (!o) return option->get_description();
        return wrap(optionDescription(*o), kLineWidth - kNameColumn);
    }

    std::string make_footer(const CLI::App*) const override {
        std::string out;
        if (!command_.examples.empty()) {
            out += "examples:\n";
            for (const std::string& e : command_.examples) out += "  " + e + "\n";
            out += "\n";
        }
        return out + "scene files: docs/SCENES.md; accepted ranges: lightcone ranges; all commands: lightcone help\n";
    }

private:
    const CommandDeclaration& command_;
};

}  // namespace

std::string optionDescription(const OptionDeclaration& o) {
    std::string text = o.help + ".";
    if (!o.choices.empty()) text += " One of: " + joined(o.choices, ", ") + ".";
    if (o.range) text += " Accepted: " + o.range->describe() + ".";
    if (!o.needs.empty()) text += " Needs " + joined(o.needs, ", ") + ".";
    if (!o.excludes.empty()) text += " Not with " + joined(o.excludes, ", ") + ".";
    if (o.repeatable) text += " May be repeated.";
    return text;
}

std::string commandHelp(const CommandDeclaration& command) {
    const auto app = makeParser(command);
    app->formatter(std::make_shared<HelpFormatter>(command));
    std::string text = app->help();
    for (std::size_t at; (at = text.find("\n\n\n")) != std::string::npos;) text.erase(at, 1);  // CLI11's gap
    return text;
}

std::string overviewHelp() {
    std::string out =
        "lightcone - what an observer sees in a relativistic spacetime\n\n"
        "usage:\n";
    for (const CommandDeclaration& c : commandDeclarations()) {
        for (const std::string& line : c.usage)
            out += "  lightcone " + c.name + (line.empty() ? "" : " " + line) + "\n";
        std::string summary = wrap(c.summary, kLineWidth - 6);
        for (std::size_t at = 0; (at = summary.find('\n', at)) != std::string::npos; at += 7)
            summary.insert(at + 1, 6, ' ');
        out += "      " + summary + "\n";
    }
    return out +
           "\nlightcone COMMAND --help (or lightcone help COMMAND): that command's options, their ranges and "
           "examples\nlightcone --version: the version, its commit and the libraries it was built with\n";
}

std::string helpMarkdown() {
    std::string out =
        "# The command line\n\n"
        "Every command's `--help`, as `./build/app/lightcone help --markdown > docs/CLI.md` writes it (a test keeps\n"
        "this file equal to the program's help, which comes from app/cli/command_declarations.cpp).\n\n"
        "```\n" +
        overviewHelp() + "```\n";
    for (const CommandDeclaration& c : commandDeclarations())
        out += "\n## lightcone " + c.name + "\n\n```\n" + commandHelp(c) + "```\n";
    return out;
}

namespace {

// A value that names a file or a folder: completed from the file system.
bool namesFile(const OptionDeclaration& o) {
    return o.value == "DIR" || o.value.find('.') != std::string::npos || o.value.find('/') != std::string::npos;
}

std::string completionCase(const CommandDeclaration& c) {
    std::string words, files, values;
    for (const OptionDeclaration& o : c.options) {
        std::string names = o.names;
        for (char& ch : names)
            if (ch == ',') ch = '|';
        words += (words.empty() ? "" : " ") + o.names;
        if (o.flag()) continue;
        if (!o.choices.empty())
            values += "        " + names + ") COMPREPLY=($(compgen -W \"" + joined(o.choices, " ") +
                      "\" -- \"$cur\")); return ;;\n";
        else if (namesFile(o))
            files += (files.empty() ? "" : "|") + names;
        else
            values += "        " + names + ") return ;;\n";  // a number or a NAME=VALUE: nothing to offer
    }
    for (char& ch : words)
        if (ch == ',') ch = ' ';
    std::string out = "    " + c.name + ")\n      case \"$prev\" in\n" + values;
    if (!files.empty()) out += "        " + files + ") COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n";
    out += "      esac\n      opts=\"" + words + "\" ;;\n";
    return out;
}

}  // namespace

std::string bashCompletion() {
    std::vector<std::string> names;
    for (const CommandDeclaration& c : commandDeclarations()) names.push_back(c.name);
    std::string cases;
    for (const CommandDeclaration& c : commandDeclarations()) {
        if (c.name == "help")
            cases += "    help) COMPREPLY=($(compgen -W \"" + joined(names, " ") +
                     " --markdown --man\" -- \"$cur\")); return ;;\n";
        else if (c.name == "completion")
            cases += "    completion) COMPREPLY=($(compgen -W \"bash\" -- \"$cur\")); return ;;\n";
        else
            cases += completionCase(c);
    }
    return "# bash completion for lightcone, generated from its option declarations:\n"
           "#   source <(lightcone completion bash)\n"
           "_lightcone() {\n"
           "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\" opts=\"\"\n"
           "  if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
           "    COMPREPLY=($(compgen -W \"" +
           joined(names, " ") +
           "\" -- \"$cur\")); return\n"
           "  fi\n"
           "  case \"${COMP_WORDS[1]}\" in\n" +
           cases +
           "  esac\n"
           "  if [[ \"$cur\" == -* ]]; then COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"));\n"
           "  else COMPREPLY=($(compgen -f -- \"$cur\")); fi\n"
           "}\n"
           "complete -o filenames -F _lightcone lightcone\n";
}

}  // namespace lc::cli
