#pragma once
// Surface and sky patterns, sampled by (u, v) in [0,1]^2. Linear RGB.
#include "core/numerics/types.hpp"

#include <algorithm>
#include <memory>
#include <vector>

namespace lc {

class Texture {
public:
    virtual ~Texture() = default;
    virtual Vec3 sample(double u, double v) const = 0;
};
using TexturePtr = std::shared_ptr<const Texture>;

class CheckerTexture final : public Texture {
public:
    CheckerTexture(int cellsU, int cellsV, Vec3 a, Vec3 b) : nu_(cellsU), nv_(cellsV), a_(a), b_(b) {}
    Vec3 sample(double u, double v) const override {
        const long iu = static_cast<long>(std::floor(u * nu_)), iv = static_cast<long>(std::floor(v * nv_));
        return ((iu + iv) & 1) ? b_ : a_;
    }
    int cellsU() const { return nu_; }
    int cellsV() const { return nv_; }

private:
    int nu_, nv_;
    Vec3 a_, b_;
};

class SolidTexture final : public Texture {
public:
    explicit SolidTexture(Vec3 c) : c_(c) {}
    Vec3 sample(double, double) const override { return c_; }
    const Vec3& colour() const { return c_; }

private:
    Vec3 c_;
};

// An image held in memory (loaded by readers/, which owns file formats), bilinear, wraps in u.
class ImageTexture final : public Texture {
public:
    ImageTexture(int width, int height, std::vector<float> rgb) : w_(width), h_(height), rgb_(std::move(rgb)) {}
    Vec3 sample(double u, double v) const override {
        const double x = (u - std::floor(u)) * w_ - 0.5, y = std::clamp(v, 0.0, 1.0) * h_ - 0.5;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        auto px = [&](int xi, int yi) {
            xi = ((xi % w_) + w_) % w_;
            yi = std::clamp(yi, 0, h_ - 1);
            const float* p = &rgb_[3 * (static_cast<std::size_t>(yi) * w_ + xi)];
            return Vec3(p[0], p[1], p[2]);
        };
        return (1 - fy) * ((1 - fx) * px(x0, y0) + fx * px(x0 + 1, y0)) +
               fy * ((1 - fx) * px(x0, y0 + 1) + fx * px(x0 + 1, y0 + 1));
    }
    int width() const { return w_; }
    int height() const { return h_; }
    const std::vector<float>& texels() const { return rgb_; }  // RGB, row 0 at v = 0

private:
    int w_, h_;
    std::vector<float> rgb_;
};

}  // namespace lc
