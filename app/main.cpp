// SPDX-License-Identifier: BSD-3-Clause
// lightcone: command-line entry point. Each command lives in its own file.
#include "app/cli/command_line.hpp"
#include "app/cli/version.hpp"
#include "app/commands/commands.hpp"
#include "app/distributed/distributed_tasks.hpp"
#include "core/input/ranges.hpp"
#include "core/metrics/factory.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/json_document.hpp"

#include <algorithm>
#include <iostream>

namespace {

// --help or -h anywhere but where an option's value belongs (`--data --help` is a missing file
// name: the command's own parser says so).
bool asksForHelp(const std::string& cmd, const std::vector<std::string>& args) {
    const lc::cli::CommandDeclaration* command = lc::cli::findCommand(cmd);
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] != "--help" && args[i] != "-h") continue;
        const lc::cli::OptionDeclaration* before = command && i > 0 ? command->option(args[i - 1]) : nullptr;
        if (!before || before->flag()) return true;
    }
    return false;
}

int unknownCommand(const std::string& name) {
    std::cerr << "lightcone: unknown command '" << name << "'\n\n" << lc::cli::overviewHelp();
    return 2;
}

// Prints a failure and returns its exit code. Under mpirun a failure every rank shares is
// printed once, by rank 0; any other may have struck some ranks only, while the others wait for
// them in the task loop: it is printed with the rank's number and ends the whole run.
int fail(const lc::dist::Processes& processes, const std::string& message, int code, bool onEveryRank) {
    if (!processes.distributed() || (onEveryRank && processes.root())) std::cerr << message << "\n";
    if (!processes.distributed() || onEveryRank) return code;
    std::cerr << "rank " << processes.rank() << ": " << message << "\n";
    processes.abortRun(code);
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    // Under mpirun every rank runs this program (app/distributed/).
    const lc::dist::Processes processes(argc, argv);
    if (argc < 2) {
        std::cerr << lc::cli::overviewHelp();
        return 2;
    }
    const std::string cmd = argv[1];
    if (cmd == "--version" || cmd == "-V") {  // before anything is loaded: it answers at once
        std::cout << lc::cli::versionText();
        return 0;
    }
    try {
        const std::vector<std::string> args(argv + 2, argv + argc);
        // `lightcone COMMAND --help` and `lightcone help COMMAND`: that command's help.
        const std::string helpFor = asksForHelp(cmd, args) ? cmd : cmd == "help" && !args.empty() ? args[0] : "";
        if (helpFor == "--markdown") {
            std::cout << lc::cli::helpMarkdown();
            return 0;
        }
        if (helpFor == "--man") {  // the installed man pages (cmake/LightconeInstall.cmake)
            if (args.size() != 2 || args[1].empty() || args[1][0] == '-')
                throw std::invalid_argument("help --man expects one folder: lightcone help --man DIR");
            lc::io::checkOutputFolder(args[1], "--man");
            lc::io::writeFolderAtomically(args[1], lc::cli::manPages());
            return 0;
        }
        if (!helpFor.empty()) {
            const lc::cli::CommandDeclaration* command = lc::cli::findCommand(helpFor);
            if (!command) return unknownCommand(helpFor);
            std::cout << lc::cli::commandHelp(*command);
            return 0;
        }
        if (cmd == "render") return lc::cli::runRender(args);
        if (cmd == "animate") return lc::cli::runAnimate(args);
        if (cmd == "sweep") return lc::cli::runSweep(args);
        if (cmd == "trace") return lc::cli::runTrace(args);
        if (cmd == "metric") return lc::cli::runMetric(args);
        if (cmd == "images") return lc::cli::runImages(args);
        if (cmd == "shade") return lc::cli::runShade(args);
#ifdef LIGHTCONE_WITH_VTK
        if (cmd == "diagram") return lc::cli::runDiagram(args);
        if (cmd == "figure") return lc::cli::runFigure(args);
        if (cmd == "export") return lc::cli::runExport(args);
        if (cmd == "curvature") return lc::cli::runCurvature(args);
#endif
        if (cmd == "ranges") {
            if (!args.empty()) throw std::invalid_argument("ranges takes no arguments, got '" + args[0] + "'");
            std::cout << lc::input::rangesMarkdown() << "\n" << lc::metricParametersMarkdown();
            return 0;
        }
        if (cmd == "completion") {
            if (args.size() != 1 || args[0] != "bash")
                throw std::invalid_argument("completion expects the shell: lightcone completion bash");
            std::cout << lc::cli::bashCompletion();
            return 0;
        }
        if (cmd == "help" || cmd == "--help" || cmd == "-h") {
            std::cout << lc::cli::overviewHelp();
            return 0;
        }
        return unknownCommand(cmd);
    } catch (const lc::dist::TaskFailed& e) {  // thrown on every rank alike
        return fail(processes, "lightcone " + cmd + ": " + e.what(), 1, true);
    } catch (const lc::io::InputError& e) {
        return fail(processes, std::string("lightcone: ") + e.what(), 3, false);
    } catch (const std::bad_alloc&) {
        return fail(processes, "lightcone " + cmd + ": out of memory (hint: a smaller image, mesh or mesh_resolution)",
                    1, false);
    } catch (const std::invalid_argument& e) {
        return fail(processes, "lightcone " + cmd + ": " + e.what(), 2, false);
    } catch (const std::exception& e) {
        return fail(processes, "lightcone " + cmd + ": " + e.what(), 1, false);
    }
}
