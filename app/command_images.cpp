// `lightcone images`: every image of a static point in the Goedel universe, as JSON.
#include "app/commands.hpp"
#include "core/godel/images.hpp"

#include <json/json.h>

#include <iostream>

namespace lc::cli {

int runImages(const Args& args) {
    args.allow({"--a", "--observer", "--point", "--cylindrical", "--windings", "--future"});
    const double a = args.number("--a", 1.0);
    if (!(a > 0)) throw std::invalid_argument("--a must be > 0");
    Vec4 observer = Vec4::Zero();
    if (args.has("--observer")) {
        const auto o = args.numbers("--observer", 4);
        observer = Vec4(o[0], o[1], o[2], o[3]);
    }
    Vec3 point;
    if (args.has("--cylindrical")) {
        const auto c = args.numbers("--cylindrical", 3);
        point = Vec3(c[0] * std::cos(c[1]), c[0] * std::sin(c[1]), c[2]);
    } else {
        const auto p = args.numbers("--point", 3);
        point = Vec3(p[0], p[1], p[2]);
    }
    const int windings = static_cast<int>(args.number("--windings", 2));
    if (windings < 0 || windings > 1000) throw std::invalid_argument("--windings must be in [0, 1000]");
    const godel::ObserverView view(a, observer);
    const godel::ImageSet set = view.images(point, windings, args.has("--future") ? +1 : -1);

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
        j["psi"] = im.psi;
        j["phi0"] = im.phi0;
        j["k3"] = im.k3;
        j["lambda"] = im.lambda;
        j["emission_time"] = im.emissionTime;
        j["frequency_ratio"] = im.frequencyRatio;
        for (int i = 0; i < 3; ++i) j["direction"].append(im.direction(i));
        if (im.ring) j["ring"] = true;
        out["images"].append(j);
    }
    Json::StreamWriterBuilder w;
    w["indentation"] = "  ";
    w["precision"] = 15;
    std::cout << Json::writeString(w, out) << "\n";
    return set.status == godel::ImageStatus::InvalidInput ? 1 : 0;
}

}  // namespace lc::cli
