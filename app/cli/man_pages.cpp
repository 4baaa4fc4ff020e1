// SPDX-License-Identifier: BSD-3-Clause
// `lightcone help --man DIR`: man pages in roff (man(7)), one per command, from the declarations
// that also make --help, docs/CLI.md and the completion, so the installed pages say what the
// program accepts. Written by hand: help2man would parse our own --help back into structure
// the declarations already hold.
#include "app/cli/command_line.hpp"
#include "readers/io/provenance.hpp"

#include <cctype>

namespace lc::cli {
namespace {

// Text as roff shows it: backslashes escaped, '-' as \- (a hyphen-minus users can search
// and copy), and a line starting with '.' or '\'' kept from reading as a request.
std::string roffText(const std::string& text) {
    std::string out;
    bool lineStart = true;
    for (char ch : text) {
        if (lineStart && (ch == '.' || ch == '\'')) out += "\\&";
        if (ch == '\\')
            out += "\\e";
        else if (ch == '-')
            out += "\\-";
        else
            out += ch;
        lineStart = ch == '\n';
    }
    return out;
}

std::string upper(std::string s) {
    for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return s;
}

std::string header(const std::string& page, const std::string& summary) {
    return ".TH " + upper(page) + " 1 \"\" \"Lightcone " + io::versionNumber() +
           "\" \"Lightcone Manual\"\n"
           ".SH NAME\n" +
           roffText(page) + " \\- " + roffText(summary) + "\n";
}

// "-o,--output" and "IMAGE.png": \fB\-o\fR, \fB\-\-output\fR \fIIMAGE.png\fR
std::string optionTag(const OptionDeclaration& o) {
    std::string tag, name;
    const auto flush = [&] {
        if (!name.empty()) tag += (tag.empty() ? "" : ", ") + std::string("\\fB") + roffText(name) + "\\fR";
        name.clear();
    };
    for (char ch : o.names)
        if (ch == ',')
            flush();
        else
            name += ch;
    flush();
    return o.flag() ? tag : tag + " \\fI" + roffText(o.value) + "\\fR";
}

std::string seeAlso(const std::string& except) {
    std::string out = ".SH SEE ALSO\n";
    std::string pages = except == "lightcone" ? "" : "\\fBlightcone\\fR(1)";
    for (const CommandDeclaration& c : commandDeclarations())
        if ("lightcone-" + c.name != except)
            pages += (pages.empty() ? "" : ", ") + std::string("\\fBlightcone\\-") + roffText(c.name) + "\\fR(1)";
    return out + pages +
           "\n.PP\nScene files: SCENES.md; metrics typed as text: METRICS.md; the physics: PHYSICS.md "
           "(in the documentation folder, e.g. /usr/share/doc/lightcone/docs). "
           "Scenes given by a bare name are looked for in $LIGHTCONE_DATA_PATH and the installed "
           "share/lightcone/data.\n";
}

std::string commandPage(const CommandDeclaration& c) {
    const std::string page = "lightcone-" + c.name;
    std::string out = header(page, c.summary) + ".SH SYNOPSIS\n.nf\n";
    for (const std::string& line : c.usage)
        out += "\\fBlightcone " + roffText(c.name) + "\\fR" + (line.empty() ? "" : " " + roffText(line)) + "\n";
    out += ".fi\n.SH DESCRIPTION\n" + roffText(c.summary) + ".\n";
    if (!c.options.empty()) {
        out += ".SH OPTIONS\n";
        std::string group;
        for (const OptionDeclaration& o : c.options) {
            if (o.group != group) out += ".SS " + roffText(o.group) + "\n";
            group = o.group;
            out += ".TP\n" + optionTag(o) + "\n" + roffText(optionDescription(o)) + "\n";
        }
    }
    if (!c.examples.empty()) {
        out += ".SH EXAMPLES\n.nf\n";
        for (const std::string& e : c.examples) out += roffText(e) + "\n";
        out += ".fi\n";
    }
    out +=
        ".SH EXIT STATUS\n0 on success; 2 for a wrong command line; 3 for a wrong input file (the message "
        "names file, line and field); 1 for any other failure.\n";
    return out + seeAlso(page);
}

std::string overviewPage() {
    std::string out = header("lightcone", "what an observer sees in a relativistic spacetime") +
                      ".SH SYNOPSIS\n.nf\n\\fBlightcone\\fR \\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n"
                      "\\fBlightcone \\-\\-version\\fR\n.fi\n.SH COMMANDS\n";
    for (const CommandDeclaration& c : commandDeclarations())
        out += ".TP\n\\fBlightcone\\-" + roffText(c.name) + "\\fR(1)\n" + roffText(c.summary) + "\n";
    out +=
        ".SH ENVIRONMENT\n.TP\n\\fBLIGHTCONE_DATA_PATH\\fR\nFolders (separated by ':') searched for a scene "
        "or metric file given by a name that is not a file in the working folder, before the installed "
        "scenes.\n";
    return out + seeAlso("lightcone");
}

}  // namespace

std::vector<std::pair<std::string, std::string>> manPages() {
    std::vector<std::pair<std::string, std::string>> pages{{"lightcone.1", overviewPage()}};
    for (const CommandDeclaration& c : commandDeclarations())
        pages.emplace_back("lightcone-" + c.name + ".1", commandPage(c));
    return pages;
}

}  // namespace lc::cli
