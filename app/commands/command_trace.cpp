// SPDX-License-Identifier: BSD-3-Clause
// `lightcone trace`: one geodesic, reported as JSON.
#include "app/commands/commands.hpp"
#include "core/spacetime/named_observer.hpp"
#include "core/curvature/jacobi_map.hpp"
#include "core/scene/observer_ray.hpp"
#include "core/input/number_text.hpp"
#include "core/metrics/factory.hpp"
#include "core/spacetime/scattering.hpp"
#include "readers/io/json_document.hpp"

#include <json/json.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace lc::cli {
namespace {

// JSON has no NaN: a non-finite number in the report is a failure, not a "null".
void requireFinite(const Json::Value& v, const std::string& path) {
    if (v.isDouble() && !std::isfinite(v.asDouble()))
        throw std::runtime_error("the result '" + path + "' is not finite (the ray met a singularity of the chart?)");
    if (v.isArray())
        for (Json::ArrayIndex i = 0; i < v.size(); ++i) requireFinite(v[i], path + "[" + std::to_string(i) + "]");
    if (v.isObject())
        for (const auto& k : v.getMemberNames()) requireFinite(v[k], path.empty() ? k : path + "." + k);
}

// The figure a physicist quotes: the global error of the answer, estimated by tracing the same ray
// again at a tolerance 100 times tighter (the difference is the first run's error to within about
// a hundredth of itself for an adaptive stepper whose error follows its tolerance). For a
// deflection when the ray escaped; otherwise for the end position when both runs stopped at the
// same affine length (--max-affine). Costs one more, tighter, integration of the ray.
void appendErrorEstimate(Json::Value& out, const Spacetime& st, const PhasePoint& start, const TraceOptions& opt,
                         const TraceResult& first) {
    if (opt.stepper == StepperKind::RK4) return;  // fixed steps: no tolerance to tighten
    TraceOptions tighter = opt;
    tighter.absTol = tighter.relTol = std::max(opt.relTol / 100, 1e-15);
    tighter.maxSteps = std::max<std::size_t>(opt.maxSteps, 4 * first.steps);
    Json::Value& e = out["error_estimate"];
    char method[96];
    std::snprintf(method, sizeof method, "the same ray again at tolerance %.0e (%.0f times tighter)", tighter.relTol,
                  opt.relTol / tighter.relTol);
    e["method"] = method;
    if (out.isMember("deflection")) {
        const DeflectionResult d = measureDeflection(st, start, tighter);
        if (d.trace.reason == StopReason::Escaped)
            e["deflection"] = std::abs(d.deflection - out["deflection"].asDouble());
    } else if (first.reason == StopReason::MaxAffine) {
        const TraceResult r = traceGeodesic(st, start, tighter);
        if (r.reason == StopReason::MaxAffine)
            e["end_position"] = (r.end.x - first.end.x).norm() / std::max(1.0, first.end.x.norm());
    }
    if (e.size() == 1) e["unavailable"] = "no deflection and no end at a fixed affine length to compare";
}

}  // namespace

int runTrace(const std::vector<std::string>& argv) {
    const TraceCommandOptions o = parseTraceOptions(argv);
    const SpacetimePtr st = traceSpacetime(o);
    TraceOptions opt = o.trace;

    PhasePoint start;
    Vec4 velocity = Vec4::Unit(0);
    if (o.impact) {
        if (!st->asymptoticallyFlat()) throw std::invalid_argument("--impact needs an asymptotically flat metric");
        start = impactParameterRay(*st, *o.impact, o.distance);
        opt.escapeRadius = o.distance;
    } else {
        try {
            velocity = o.observerVelocity ? *o.observerVelocity
                                          : namedObserverVelocity(*st, o.event, *namedObserverFrom(o.observer));
            start = observerRay(*st, o.event, velocity, o.direction, o.future);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string("option --observer: ") + e.what());
        }
        opt.escapeRadius = escapeRadiusForRayFrom(start.x);
    }
    if (!start.p.allFinite() || !start.x.allFinite())
        throw std::invalid_argument("the ray cannot start here (a singularity of the chart at --event?)");

    Json::Value out;
    out["metric"] = st->name();
    for (const auto& [k, v] : st->parameters()) out["parameters"][k] = v;
    out["stepper"] = stepperName(opt.stepper);
    out["tolerance"] = opt.relTol;
    if (!o.impact) {
        out["observer"]["name"] = o.observer;
        out["observer"]["velocity"] = io::jsonArray(LocalFrame::withVelocity(*st, o.event, velocity).e[0]);
    }
    out["start"]["x"] = io::jsonArray(start.x);
    out["start"]["p"] = io::jsonArray(start.p);
    TraceResult r;
    if (st->asymptoticallyFlat()) {
        const DeflectionResult d = measureDeflection(*st, start, opt);
        r = d.trace;
        out["impact_parameter"] = d.impact;
        // A deflection exists for rays that escaped; anything else prints none, only why (no null:
        // a JSON reader would take it for a number).
        if (r.reason == StopReason::Escaped) {
            out["deflection"] = d.deflection;
            out["angle_between_directions"] = d.angleBetween;
        } else {
            out["no_deflection_because"] = "the ray did not escape: it stopped at " + stopReasonName(r.reason);
        }
    } else {
        r = traceGeodesic(*st, start, opt);
    }
    // --max-affine, the horizon, escape are ends; max steps and step underflow are the tracer
    // giving up before the end asked for.
    const bool unanswered = r.reason == StopReason::MaxSteps || r.reason == StopReason::StepUnderflow ||
                            r.reason == StopReason::ConstraintBlowUp;
    out["end"]["x"] = io::jsonArray(r.end.x);
    out["end"]["p"] = io::jsonArray(r.end.p);
    out["affine"] = r.affine;
    out["reason"] = stopReasonName(r.reason);
    out["steps"] = static_cast<Json::UInt64>(r.steps);
    out["rejected_steps"] = static_cast<Json::UInt64>(r.rejected);
    out["max_hamiltonian_drift"] = r.maxHamiltonianDrift;
    appendErrorEstimate(out, *st, start, opt, r);
    if (o.sourcePlane) {
        // The same ray traced again with its Jacobi map (core/curvature/jacobi_map), to the plane.
        const auto& v = *o.sourcePlane;
        SourcePlane plane;
        plane.point = Vec3(v[0], v[1], v[2]);
        plane.normal = Vec3(v[3], v[4], v[5]).normalized();
        const LocalFrame observer = LocalFrame::withVelocity(*st, o.event, velocity);
        const JacobiRayResult j =
            traceJacobiRay(*st, observer, o.direction, plane,
                           {opt.relTol, std::isfinite(opt.maxAffine) ? opt.maxAffine : 1e15, opt.maxSteps});
        if (!j.reached)
            throw std::runtime_error("option --source-plane: the ray does not meet the plane (it stopped after " +
                                     std::to_string(j.steps) + " steps at affine " + std::to_string(j.affine) + ")");
        // The unlensed distance from the observer to the plane, along its normal.
        const double distance = std::abs(plane.normal.dot(plane.point - o.event.tail<3>()));
        Json::Value& jm = out["source_plane"];
        jm["reached"] = io::jsonArray(j.x);
        jm["affine"] = j.affine;
        jm["jacobi_map"] = Json::Value(Json::arrayValue);
        for (int row = 0; row < 2; ++row) {
            Json::Value r2(Json::arrayValue);
            r2.append(j.map(row, 0));
            r2.append(j.map(row, 1));
            jm["jacobi_map"].append(r2);
        }
        jm["distance"] = distance;
        jm["magnification"] = j.magnification(distance);
        jm["steps"] = static_cast<Json::UInt64>(j.steps);
    }
    requireFinite(out, "");
    Json::StreamWriterBuilder w;
    w["indentation"] = "  ";
    w["precision"] = 17;
    std::cout << Json::writeString(w, out) << "\n";
    // A momentum grown without bound while the affine length stalls is no tolerance problem: the ray
    // meets a horizon at finite affine length, with infinite blueshift (a superluminal warp
    // bubble's front wall), where the chart ends.
    const double growth = r.end.p.norm() / std::max(start.p.norm(), 1e-300);
    if (r.reason == StopReason::StepUnderflow && growth > 1e6)
        std::cerr << "lightcone trace: the ray's momentum grew " << input::significantDigits(growth, 2)
                  << "-fold as its affine length stalled at " << input::significantDigits(r.affine, 6)
                  << ": it reaches a horizon at finite affine length, infinitely blueshifted (as at a superluminal "
                     "warp bubble's front wall), where the chart ends\n";
    else if (unanswered)
        std::cerr << "lightcone trace: the ray stopped at " << stopReasonName(r.reason) << " after " << r.steps
                  << " steps, before " << (st->asymptoticallyFlat() ? "it escaped (no deflection)" : "--max-affine")
                  << ": raise --max-steps, or give a shorter --max-affine\n";
    return unanswered ? 4 : 0;
}

}  // namespace lc::cli
