// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Surface and sky patterns, sampled by (u, v) in [0,1]^2. Linear RGB.
#include "core/numerics/types.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace lc {

struct LightMap;

class Texture {
public:
    virtual ~Texture() = default;
    virtual Vec3 sample(double u, double v) const = 0;
    // A texture of black-body light (a star field, lc::StarSky): the map of brightness and
    // temperature it is drawn from, which the shading shifts by each pixel's g; null for a colour.
    virtual const LightMap* lightMap() const { return nullptr; }
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

// Where (u, v) falls in a w x h image in texel units, texel (i, j) centred at (i, j): u wraps, v is
// clamped to the image. And the bilinear blend of the four texels around that point, (fx, fy) its
// fractions past texel (x0, y0). For every scalar: ImageTexture::sample calls them in double, the
// post-renderer's atlas lookup (lcTexelPosition, lcBilinear) is generated from them.
template <class S>
Eigen::Matrix<S, 2, 1> texelPosition(const S& u, const S& v, const S& width, const S& height) {
    using std::floor;
    using std::max;
    using std::min;
    return Eigen::Matrix<S, 2, 1>((u - floor(u)) * width - S(0.5), min(max(v, S(0.0)), S(1.0)) * height - S(0.5));
}
// The texel a whole-numbered (x, y) addresses in a w x h image: x wraps, y is clamped. Written in
// S for the generated GLSL twin (lcTexelIndex); floor((x + 0.5) / w) keeps the wrap exact where a
// division rounds (GLSL's is not correctly rounded).
template <class S>
Eigen::Matrix<S, 2, 1> texelIndex(const S& x, const S& y, const S& width, const S& height) {
    using std::floor;
    using std::max;
    using std::min;
    return Eigen::Matrix<S, 2, 1>(x - width * floor((x + S(0.5)) / width), min(max(y, S(0.0)), height - S(1.0)));
}
template <class S>
Eigen::Matrix<S, 3, 1> bilinear(const Eigen::Matrix<S, 3, 1>& c00, const Eigen::Matrix<S, 3, 1>& c10,
                                const Eigen::Matrix<S, 3, 1>& c01, const Eigen::Matrix<S, 3, 1>& c11, const S& fx,
                                const S& fy) {
    return (S(1.0) - fy) * ((S(1.0) - fx) * c00 + fx * c10) + fy * ((S(1.0) - fx) * c01 + fx * c11);
}

// An image held in memory (loaded by readers/, which owns file formats), bilinear, wraps in u.
class ImageTexture final : public Texture {
public:
    ImageTexture(int width, int height, std::vector<float> rgb) : w_(width), h_(height), rgb_(std::move(rgb)) {}
    Vec3 sample(double u, double v) const override {
        const Vec2 position = texelPosition(u, v, double(w_), double(h_));
        const double x = position(0), y = position(1);
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        auto px = [&](int xi, int yi) {
            const Vec2 texel = texelIndex(double(xi), double(yi), double(w_), double(h_));
            const float* p = &rgb_[3 * (static_cast<std::size_t>(texel(1)) * w_ + static_cast<std::size_t>(texel(0)))];
            return Vec3(p[0], p[1], p[2]);
        };
        return bilinear<double>(px(x0, y0), px(x0 + 1, y0), px(x0, y0 + 1), px(x0 + 1, y0 + 1), fx, fy);
    }
    int width() const { return w_; }
    int height() const { return h_; }
    const std::vector<float>& texels() const { return rgb_; }  // RGB, row 0 at v = 0

private:
    int w_, h_;
    std::vector<float> rgb_;
};

// Black-body light over the sky: per texel (ImageTexture's layout, row 0 at v = 0) the brightness
// b and b T, so that a bilinear blend (here, or a GPU's linear filter of the same float texels)
// gives the brightness and the brightness-weighted temperature.
struct LightMap {
    struct Light {
        double brightness = 0, temperature = 0;  // temperature 0 where there is no light
    };
    int width = 0, height = 0;
    std::vector<float> texels;  // b, b T per texel
    Light at(double u, double v) const {
        const Vec2 position = texelPosition(u, v, double(width), double(height));
        const int x0 = static_cast<int>(std::floor(position(0))), y0 = static_cast<int>(std::floor(position(1)));
        const double fx = position(0) - x0, fy = position(1) - y0;
        auto texel = [&](int xi, int yi) {
            const Vec2 t = texelIndex(double(xi), double(yi), double(width), double(height));
            const float* p = &texels[2 * (static_cast<std::size_t>(t(1)) * width + static_cast<std::size_t>(t(0)))];
            return Vec3(p[0], p[1], 0);
        };
        const Vec3 c =
            bilinear<double>(texel(x0, y0), texel(x0 + 1, y0), texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx, fy);
        return c(0) > 0 ? Light{c(0), c(1) / c(0)} : Light{};
    }
};

}  // namespace lc
