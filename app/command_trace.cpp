// `lightcone trace`: one geodesic, reported as JSON.
#include "app/commands.hpp"
#include "core/frame.hpp"
#include "core/metrics/factory.hpp"
#include "core/scattering.hpp"

#include <json/json.h>

#include <iostream>
#include <memory>

namespace lc::cli {
namespace {

Json::Value vec(const Vec4& v) {
    Json::Value a(Json::arrayValue);
    for (int i = 0; i < 4; ++i) a.append(v(i));
    return a;
}

std::map<std::string, double> metricParams(const Args& args) {
    std::map<std::string, double> p;
    for (const auto& kv : args.all("--param")) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) throw std::invalid_argument("--param expects NAME=VALUE, got '" + kv + "'");
        p[kv.substr(0, eq)] = std::stod(kv.substr(eq + 1));
    }
    return p;
}

}  // namespace

int runTrace(const Args& args) {
    args.allow({"--metric", "--param", "--event", "--direction", "--impact", "--distance", "--stepper", "--tolerance",
                "--max-affine", "--max-steps", "--initial-step", "--future"});
    const SpacetimePtr st = makeSpacetime(args.get("--metric", "schwarzschild"), metricParams(args));
    TraceOptions opt;
    opt.stepper = parseStepper(args.get("--stepper", "fehlberg78"));  // best accuracy per cost for single rays (docs/PERFORMANCE.md)
    opt.absTol = opt.relTol = args.number("--tolerance", 1e-12);
    opt.maxAffine = args.number("--max-affine", 1e8);
    opt.maxSteps = static_cast<std::size_t>(args.number("--max-steps", 1e6));
    opt.initialStep = args.number("--initial-step", 1e-2);

    PhasePoint start;
    if (args.has("--impact")) {
        if (!st->asymptoticallyFlat()) throw std::invalid_argument("--impact needs an asymptotically flat metric");
        const double D = args.number("--distance", 1e6);
        start = impactParameterRay(*st, args.number("--impact", 0), D);
        opt.escapeRadius = D;
    } else {
        const auto e = args.numbers("--event", 4);
        const auto d = args.numbers("--direction", 3);
        start.x = Vec4(e[0], e[1], e[2], e[3]);
        const LocalFrame f = LocalFrame::staticObserver(*st, start.x);
        start.p = f.pastNullMomentum(*st, Vec3(d[0], d[1], d[2]));
        if (args.has("--future")) start.p = -st->metric(start.x) * (st->inverseMetric(start.x) * start.p);  // reverse
        opt.escapeRadius = std::max(1e3, 10 * start.x.tail<3>().norm());
    }

    Json::Value out;
    out["metric"] = st->name();
    for (const auto& [k, v] : st->parameters()) out["parameters"][k] = v;
    out["stepper"] = stepperName(opt.stepper);
    out["tolerance"] = opt.relTol;
    out["start"]["x"] = vec(start.x);
    out["start"]["p"] = vec(start.p);
    TraceResult r;
    if (st->asymptoticallyFlat()) {
        const DeflectionResult d = measureDeflection(*st, start, opt);
        r = d.trace;
        out["impact_parameter"] = d.impact;
        out["deflection"] = d.deflection;
        out["angle_between_directions"] = d.angleBetween;
    } else {
        r = traceGeodesic(*st, start, opt);
    }
    out["end"]["x"] = vec(r.end.x);
    out["end"]["p"] = vec(r.end.p);
    out["affine"] = r.affine;
    out["reason"] = stopReasonName(r.reason);
    out["steps"] = static_cast<Json::UInt64>(r.steps);
    out["rejected_steps"] = static_cast<Json::UInt64>(r.rejected);
    out["max_hamiltonian_drift"] = r.maxHamiltonianDrift;
    Json::StreamWriterBuilder w;
    w["indentation"] = "  ";
    w["precision"] = 17;
    std::cout << Json::writeString(w, out) << "\n";
    return 0;
}

}  // namespace lc::cli
