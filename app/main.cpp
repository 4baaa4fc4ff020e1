// lightcone: command-line entry point. Each command lives in its own file.
#include "app/commands.hpp"
#include "app/distributed/distributed_tasks.hpp"
#include "core/input/ranges.hpp"
#include "core/metrics/factory.hpp"
#include "readers/io/json_document.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

namespace {

void usage(std::ostream& os) {
    os << "lightcone - what an observer sees in a relativistic spacetime\n\n"
          "usage:\n"
          "  lightcone render (SCENE.json | --session FILE.lcsession) -o IMAGE.png [--width N] [--height N] [--stepper "
          "NAME]\n"
          "                  [--tolerance T] [--windings N] [--threads N] [--method "
          "auto|numeric|closed_form|per_vertex|polygon_distortion]\n"
          "                  [--max-affine L] [--escape-radius R] [--escape-angle RAD] (numeric tracer; default from "
          "the scene)\n"
          "                  [--look-at X,Y,Z] [--data DATA.exr] [--quiet] [--gpu [--orbit-frames N]]\n"
          "                  [--spectrum OUT.csv|OUT.svg]  (an accretion disk's observed spectrum; may be repeated)\n"
          "  lightcone animate (SCENE.json | --session FILE) -o FRAMES/%04d.png [--proper-time T0:T1:N [--motion "
          "static|free_fall]]\n"
          "                  [--pan D0:D1:N] [--orbit D0:D1:N] [--sweep FIELD=V0:V1:N] [--frames FIRST-LAST] "
          "[--resume]\n"
          "                  [--movie OUT.mp4 [--fps F]] [--data FRAMES/%04d.exr] and render's options; under mpirun\n"
          "                  the frames (and bands of rows) are shared among the ranks, as for render\n"
          "  lightcone sweep (SCENE.json | --session FILE) --sweep FIELD=V0:V1:N --table OUT.csv [--plot OUT.svg]\n"
          "                  [--windings N] [--tolerance T]  (Kerr: shadow size and offset, a disk's flux and mean "
          "redshift;\n"
          "                  Goedel: images, emission times)\n"
          "  lightcone trace --metric NAME [--param K=V]... (--event t,x,y,z --direction nx,ny,nz | --impact B\n"
          "                  [--distance D]) [--stepper NAME] [--tolerance T] [--max-affine L] [--max-steps N]\n"
          "  lightcone diagram SCENE.json -o DIAGRAM.svg|.pdf|.png [-o ...] [--windings N] [--rays N] [--size PX]\n"
          "                  [--kind r-phi|t-r]  (r-phi: the observer's plane; t-r: the spacetime diagram)\n"
          "  lightcone images [--a A] [--observer t,x,y,z] (--point x,y,z | --cylindrical r,phi,z) [--windings N]\n"
          "                  [--future]\n"
          "  lightcone export SCENE.json -o DIR [--rays N]   (VTK files for ParaView)\n"
          "  lightcone shade SCENE.json DATA.exr -o IMAGE.png [--time-window t0,t1] [--temperature K]\n"
          "  lightcone ranges                 (the accepted range of every number, as in docs/SCENES.md)\n"
          "  lightcone help [COMMAND]         (also COMMAND --help: that command's usage)\n\n"
          "steppers: rk4, cash_karp54, dopri5, fehlberg78, bulirsch_stoer\n"
          "metrics:  minkowski, schwarzschild, kerr, kerr-newman, alcubierre, godel, godel-cylindrical\n";
}

// The usage lines of one command (its line and the continuation lines after it); empty when the
// command is unknown.
std::string commandUsage(const std::string& command) {
    std::ostringstream all;
    usage(all);
    std::istringstream lines(all.str());
    std::string line, out;
    bool inside = false;
    while (std::getline(lines, line)) {
        if (line.rfind("  lightcone ", 0) == 0)
            inside = line.rfind("  lightcone " + command + " ", 0) == 0 || line == "  lightcone " + command;
        else if (line.rfind("      ", 0) != 0)
            inside = false;
        if (inside) out += line + "\n";
    }
    return out;
}

bool asksForHelp(const std::vector<std::string>& args) {
    return std::find(args.begin(), args.end(), "--help") != args.end() ||
           std::find(args.begin(), args.end(), "-h") != args.end();
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
        usage(std::cerr);
        return 2;
    }
    const std::string cmd = argv[1];
    try {
        const std::vector<std::string> args(argv + 2, argv + argc);
        // `lightcone COMMAND --help` and `lightcone help COMMAND`: that command's usage.
        const std::string helpFor = asksForHelp(args) ? cmd : cmd == "help" && !args.empty() ? args[0] : "";
        if (!helpFor.empty()) {
            const std::string text = commandUsage(helpFor);
            if (text.empty()) {
                std::cerr << "lightcone: unknown command '" << helpFor << "'\n\n";
                usage(std::cerr);
                return 2;
            }
            std::cout << "usage:\n" << text << "\nscene files: docs/SCENES.md; accepted ranges: lightcone ranges\n";
            return 0;
        }
        if (cmd == "render") return lc::cli::runRender(args);
        if (cmd == "animate") return lc::cli::runAnimate(args);
        if (cmd == "sweep") return lc::cli::runSweep(args);
        if (cmd == "trace") return lc::cli::runTrace(args);
        if (cmd == "images") return lc::cli::runImages(args);
        if (cmd == "shade") return lc::cli::runShade(args);
#ifdef LIGHTCONE_WITH_VTK
        if (cmd == "diagram") return lc::cli::runDiagram(args);
        if (cmd == "export") return lc::cli::runExport(args);
#endif
        if (cmd == "ranges") {
            std::cout << lc::input::rangesMarkdown() << "\n" << lc::metricParametersMarkdown();
            return 0;
        }
        if (cmd == "help" || cmd == "--help" || cmd == "-h") {
            usage(std::cout);
            return 0;
        }
        std::cerr << "lightcone: unknown command '" << cmd << "'\n\n";
        usage(std::cerr);
        return 2;
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
