// SPDX-License-Identifier: BSD-3-Clause
// `lightcone images`: every image of a static point in the Goedel universe, as JSON.
#include "app/commands/commands.hpp"
#include "core/godel/images.hpp"

#include <json/json.h>

#include <cmath>
#include <iostream>

namespace lc::cli {

int runImages(const std::vector<std::string>& argv) {
    const ImagesOptions o = parseImagesOptions(argv);
    const double a = o.a;
    const Vec4& observer = o.observer;
    const Vec3& point = o.point;
    const int windings = o.windings;
    const godel::ObserverView view(a, observer);
    const godel::ImageSet set = view.images(point, windings, o.future ? +1 : -1);

    Json::Value out;
    out["a"] = a;
    for (int i = 0; i < 4; ++i) out["observer"].append(observer(i));
    for (int i = 0; i < 3; ++i) out["point"].append(point(i));
    out["status"] = godel::imageStatusName(set.status);
    if (!set.message.empty()) out["message"] = set.message;
    out["images"] = Json::Value(Json::arrayValue);
    for (const auto& im : set.images) {
        Json::Value j;
        j["winding"] = im.winding;
        j["branch"] = godel::branchName(im.branch);
        // Where the observer's camera sees it: its static frame (docs/PHYSICS.md section 8), not
        // the chart the isometry moved it into.
        const Vec3 d = view.inObserverFrame(im.direction);
        const godel::SkyAngles seen = godel::skyAngles(d);
        j["psi"] = seen.psi;
        j["phi0"] = seen.phi0;
        j["k3"] = im.k3;
        j["affine"] = im.lambda;  // the name trace, render's data and Python use
        j["emission_time"] = im.emissionTime;
        j["frequency_ratio"] = im.frequencyRatio;
        for (int i = 0; i < 3; ++i) j["direction"].append(d(i));
        for (int i = 0; i < 4; ++i) j["event"].append(im.event(i));
        j["ring"] = im.ring;
        out["images"].append(j);
    }
    for (const auto& im : set.images)
        if (!std::isfinite(im.psi) || !std::isfinite(im.phi0) || !std::isfinite(im.lambda) ||
            !std::isfinite(im.emissionTime) || !std::isfinite(im.frequencyRatio) || !im.direction.allFinite())
            throw std::runtime_error("an image came out non-finite (winding " + std::to_string(im.winding) + ")");
    Json::StreamWriterBuilder w;
    w["indentation"] = "  ";
    w["precision"] = 15;
    std::cout << Json::writeString(w, out) << "\n";
    return set.status == godel::ImageStatus::InvalidInput ? 1 : 0;
}

}  // namespace lc::cli
