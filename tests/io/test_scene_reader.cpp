// SPDX-License-Identifier: BSD-3-Clause
// Scene files: good ones load, bad ones give errors that name file, line and field.
#include "readers/io/scene_reader.hpp"
#include "readers/io/image_io.hpp"
#include "core/render/render.hpp"

#include "core/scene/star_sky.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

using namespace lc;

namespace {

std::string errorOf(const std::string& text) {
    try {
        io::parseScene(text, "bad.json");
    } catch (const io::InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SceneReader, DefaultSceneLoads) {
    const Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    EXPECT_EQ(s.spacetime->name(), "godel");
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_DOUBLE_EQ(s.spheres[0].radius, 0.25);
    // Windings bound the ray length: (N + 1) * 2 pi a.
    EXPECT_NEAR(s.settings.trace.maxAffine, 2 * 2 * kPi, 1e-12);
}

// Asymptotically flat scenes: no affine limit unless asked for; escape radius and angle come
// from the file, are range-checked there, and are otherwise chosen from the scene
// (traceOptionsFor: outside every object, 1/100 of a pixel). Goedel charts keep their windings.
TEST(SceneReader, EscapeAndAffineLimitsComeFromTheFileOrTheScene) {
    const std::string kerr =
        "{\"metric\": {\"name\": \"kerr\", \"a\": 0.9},\n \"observer\": {\"position\": [0, 0, -30, 0]},\n"
        " \"camera\": {\"width\": 100, \"height\": 50, \"fov\": [40, 20], \"forward\": [0, 1, 0]},\n"
        " \"objects\": [{\"type\": \"sphere\", \"centre\": [0, 8, 0, 0], \"radius\": 2}]";
    const Scene automatic = io::parseScene(kerr + "}", "kerr.json");
    EXPECT_FALSE(std::isfinite(automatic.settings.trace.maxAffine));
    const TraceOptions chosen = traceOptionsFor(automatic);
    EXPECT_DOUBLE_EQ(chosen.escapeRadius, 10.0);                     // |centre| + radius
    EXPECT_NEAR(chosen.escapeAngle, 0.01 * 0.4 * kPi / 180, 1e-15);  // 0.4 degree pixels
    const Scene given = io::parseScene(
        kerr + ",\n \"render\": {\"max_affine\": 5e4, \"escape_radius\": 500, \"escape_angle\": 1e-9}}", "kerr.json");
    EXPECT_DOUBLE_EQ(given.settings.trace.maxAffine, 5e4);
    EXPECT_DOUBLE_EQ(traceOptionsFor(given).escapeRadius, 500.0);
    EXPECT_DOUBLE_EQ(traceOptionsFor(given).escapeAngle, 1e-9);
    const std::string e = errorOf(kerr + ",\n \"render\": {\"escape_angle\": -1}}");
    EXPECT_NE(e.find("bad.json:5"), std::string::npos) << e;
    EXPECT_NE(e.find("render.escape_angle"), std::string::npos) << e;
    EXPECT_NE(e.find("[1e-15, 3.2]"), std::string::npos) << e;
    const Scene cylindrical = io::parseScene(
        "{\"metric\": {\"name\": \"godel-cylindrical\", \"a\": 2}, \"observer\": {\"position\": [0, 1, 0, 0]},"
        " \"render\": {\"windings\": 3}}",
        "godel.json");
    EXPECT_NEAR(cylindrical.settings.trace.maxAffine, 4 * 2 * kPi * 2, 1e-12);
    // Ray bundles (render.magnification): the bundle's spread settles later than the direction,
    // so escape waits for the observer's distance from the hole as lever.
    const Scene bundles = io::parseScene(kerr + ",\n \"render\": {\"magnification\": true}}", "kerr.json");
    EXPECT_TRUE(bundles.settings.magnification);
    EXPECT_DOUBLE_EQ(traceOptionsFor(bundles).escapeLever, 30.0);
    EXPECT_DOUBLE_EQ(traceOptionsFor(automatic).escapeLever, 0.0);
    const std::string notABoolean = errorOf(kerr + ",\n \"render\": {\"magnification\": 1}}");
    EXPECT_NE(notABoolean.find("bad.json:5"), std::string::npos) << notABoolean;
    EXPECT_NE(notABoolean.find("render.magnification"), std::string::npos) << notABoolean;
    EXPECT_NE(notABoolean.find("expected true or false"), std::string::npos) << notABoolean;
}

TEST(SceneReader, ErrorsNameFileLineAndField) {
    const std::string e = errorOf(
        "{\n \"metric\": {\"name\": \"godel\", \"a\": 1},\n \"objects\": [\n  {\"type\": \"sphere\", \"centre\": "
        "[0,1,0,0],\n   \"radius\": -2}\n ]\n}");
    EXPECT_NE(e.find("bad.json:5"), std::string::npos) << e;
    EXPECT_NE(e.find("objects[0].radius"), std::string::npos) << e;
    EXPECT_NE(e.find("expected a number in [1e-06, 1e+06], got -2"), std::string::npos) << e;
}

TEST(SceneReader, MissingFieldIsNamed) {
    const std::string e = errorOf("{\"metric\": {\"a\": 1}}");
    EXPECT_NE(e.find("missing required field 'name'"), std::string::npos) << e;
}

TEST(SceneReader, UnknownFieldIsReportedNotIgnored) {
    const std::string e = errorOf("{\"metric\": {\"name\": \"godel\"},\n \"camrea\": {}}");
    EXPECT_NE(e.find("bad.json:2"), std::string::npos) << e;
    EXPECT_NE(e.find("unknown field"), std::string::npos) << e;
    EXPECT_NE(e.find("camera"), std::string::npos) << e;  // the hint lists the right name
}

TEST(SceneReader, WrongTypeAndBadParameters) {
    EXPECT_NE(errorOf("{\"metric\": {\"name\": \"godel\", \"a\": \"one\"}}").find("expected a number"),
              std::string::npos);
    EXPECT_NE(
        errorOf("{\"metric\": {\"name\": \"godel\", \"a\": -1}}").find("expected a number in [0.001, 1e+06], got -1"),
        std::string::npos);
    EXPECT_NE(errorOf("{\"metric\": {\"name\": \"kerr\", \"a\": 1.5}}").find("naked"), std::string::npos);
    EXPECT_NE(errorOf("{\"metric\": {\"name\": \"vaidya\"}}").find("unknown metric"), std::string::npos);
    EXPECT_NE(errorOf("{\"metric\": {\"name\": \"godel\"}, \"render\": {\"stepper\": \"euler\"}}").find("dopri5"),
              std::string::npos);
}

TEST(SceneReader, SyntaxErrorHasLine) {
    const std::string e = errorOf("{\n\"metric\": {\"name\": \"godel\",,}\n}");
    EXPECT_NE(e.find("bad.json:2"), std::string::npos) << e;
    EXPECT_NE(e.find("invalid JSON"), std::string::npos) << e;
}

TEST(SceneReader, StaticObserverInsideErgoregionIsRejected) {
    // Kerr a = 0.9, equatorial Boyer-Lindquist r = 1.9 < 2M: d/dt is spacelike there.
    const std::string e =
        errorOf("{\"metric\": {\"name\": \"kerr\", \"a\": 0.9}, \"observer\": {\"position\": [0, 2.1, 0, 0]}}");
    EXPECT_NE(e.find("no static observer here: d/dt is not timelike"), std::string::npos) << e;
    EXPECT_NE(e.find("exist here: zamo"), std::string::npos) << "the observers that do: " << e;
}

// A named observer instead of four numbers: built where the observer is; inside the ergoregion
// "static" is refused with the names that exist there, an unknown name lists the accepted ones.
TEST(SceneReader, NamedObserversAreBuiltWhereTheObserverIs) {
    const std::string kerr =
        "{\"metric\": {\"name\": \"kerr\", \"a\": 0.9},\n \"observer\": {\"position\": [0, 2.1, 0, 0],\n";
    const Scene zamo = io::parseScene(kerr + "  \"velocity\": \"zamo\"}}", "zamo.json");
    const Mat4 g = zamo.spacetime->metric(zamo.observer);
    EXPECT_NEAR(zamo.observerVelocity.dot(g * zamo.observerVelocity), 1, 1e-12);
    // Zero angular momentum: g(u, d/dphi) = 0 with d/dphi = -y d/dx + x d/dy.
    EXPECT_NEAR(zamo.observerVelocity.dot(g * Vec4(0, -zamo.observer(2), zamo.observer(1), 0)), 0, 1e-12);
    const std::string e = errorOf(kerr + "  \"velocity\": \"static\"}}");
    EXPECT_NE(e.find("bad.json:3"), std::string::npos) << e;
    EXPECT_NE(e.find("observer.velocity"), std::string::npos) << e;
    EXPECT_NE(e.find("exist here: zamo, carter, free_fall, normal"), std::string::npos) << e;
    const std::string unknown = errorOf(kerr + "  \"velocity\": \"hovering\"}}");
    EXPECT_NE(unknown.find("unknown observer 'hovering'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("static, zamo, carter, free_fall, normal"), std::string::npos) << unknown;
    const std::string warp =
        errorOf("{\"metric\": {\"name\": \"alcubierre\", \"v\": 0.5}, \"observer\": {\"velocity\": \"carter\"}}");
    EXPECT_NE(warp.find("Kerr-Newman"), std::string::npos) << warp;
}

// sky.temperature: a black-body sky for metrics with an infinity; refused elsewhere and on objects.
TEST(SceneReader, BlackBodySkyIsForSkiesOfAsymptoticallyFlatMetrics) {
    const Scene kerr = io::parseScene(
        "{\"metric\": {\"name\": \"kerr\", \"a\": 0.5}, \"observer\": {\"position\": [0, 20, 0, 0]},\n"
        " \"sky\": {\"type\": \"solid\", \"color\": [1, 1, 1], \"temperature\": 5800}}",
        "sky.json");
    ASSERT_TRUE(kerr.skyTemperature);
    EXPECT_EQ(*kerr.skyTemperature, 5800);
    const std::string godel = errorOf(
        "{\"metric\": {\"name\": \"godel\"},\n \"sky\": {\"type\": \"solid\", "
        "\"color\": [1, 1, 1], \"temperature\": 5800}}");
    EXPECT_NE(godel.find("bad.json:2"), std::string::npos) << godel;
    EXPECT_NE(godel.find("sky.temperature"), std::string::npos) << godel;
    EXPECT_NE(godel.find("shines from infinity"), std::string::npos) << godel;
    const Scene background = io::parseScene(
        "{\"metric\": {\"name\": \"kerr\"}, \"sky\": {\"type\": \"solid\", \"color\": [1, 1, 1], "
        "\"temperature\": 2.725}}",
        "cmb.json");
    EXPECT_EQ(*background.skyTemperature, 2.725);
    const std::string cold = errorOf(
        "{\"metric\": {\"name\": \"kerr\"}, \"sky\": {\"type\": \"solid\", "
        "\"color\": [1, 1, 1], \"temperature\": 0.5}}");
    EXPECT_NE(cold.find("[1, 1e+06]"), std::string::npos) << cold;
    const std::string object = errorOf(
        "{\"metric\": {\"name\": \"kerr\"}, \"objects\": [{\"type\": \"sphere\", \"centre\": [0, 8, 0, 0], "
        "\"radius\": 1, \"texture\": {\"type\": \"solid\", \"color\": [1, 1, 1], \"temperature\": 5800}}]}");
    EXPECT_NE(object.find("unknown field"), std::string::npos) << object;
}

// sky.type stars: a random field of black-body stars (docs/SCENES.md); the same seed gives the
// same stars; each field's range named when out of it; no single temperature; infinity needed.
TEST(SceneReader, StarSkyIsReadWithItsRecipeAndRefusedWhereItCannotShine) {
    const std::string kerr =
        "{\"metric\": {\"name\": \"kerr\", \"a\": 0.5}, \"observer\": {\"position\": [0, 20, 0, 0]},\n";
    const Scene stars = io::parseScene(kerr +
                                           " \"sky\": {\"type\": \"stars\", \"stars\": 50, \"seed\": 4, "
                                           "\"temperatures\": [4000, 8000], \"faintest_magnitude\": 3, \"size\": 1}}",
                                       "stars.json");
    const auto* sky = dynamic_cast<const StarSky*>(stars.sky.get());
    ASSERT_NE(sky, nullptr);
    ASSERT_EQ(sky->stars().size(), 50u);
    EXPECT_EQ(sky->sizeDegrees(), 1);
    StarFieldRecipe recipe;
    recipe.stars = 50;
    recipe.seed = 4;
    recipe.minTemperature = 4000;
    recipe.maxTemperature = 8000;
    recipe.faintestMagnitude = 3;
    const std::vector<Star> expected = randomStars(recipe);
    for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(sky->stars()[k].direction, expected[k].direction);
        EXPECT_EQ(sky->stars()[k].temperature, expected[k].temperature);
        EXPECT_EQ(sky->stars()[k].brightness, expected[k].brightness);
    }
    EXPECT_FALSE(stars.skyTemperature);
    const std::string single = errorOf(kerr + " \"sky\": {\"type\": \"stars\", \"temperature\": 5800}}");
    EXPECT_NE(single.find("unknown field"), std::string::npos) << single;
    const std::string reversed = errorOf(kerr + " \"sky\": {\"type\": \"stars\", \"temperatures\": [9000, 3000]}}");
    EXPECT_NE(reversed.find("bad.json:2"), std::string::npos) << reversed;
    EXPECT_NE(reversed.find("sky.temperatures"), std::string::npos) << reversed;
    EXPECT_NE(reversed.find("hottest below the coolest"), std::string::npos) << reversed;
    const std::string tiny = errorOf(kerr + " \"sky\": {\"type\": \"stars\", \"size\": 0.01}}");
    EXPECT_NE(tiny.find("sky.size"), std::string::npos) << tiny;
    EXPECT_NE(tiny.find("[0.18, 10]"), std::string::npos) << tiny;
    const std::string many = errorOf(kerr + " \"sky\": {\"type\": \"stars\", \"stars\": 1e7}}");
    EXPECT_NE(many.find("sky.stars"), std::string::npos) << many;
    const std::string godel = errorOf("{\"metric\": {\"name\": \"godel\"},\n \"sky\": {\"type\": \"stars\"}}");
    EXPECT_NE(godel.find("bad.json:2"), std::string::npos) << godel;
    EXPECT_NE(godel.find("shines from infinity"), std::string::npos) << godel;
    const std::string object = errorOf(
        "{\"metric\": {\"name\": \"kerr\"}, \"objects\": [{\"type\": \"sphere\", \"centre\": [0, 8, 0, 0], "
        "\"radius\": 1, \"texture\": {\"type\": \"stars\"}}]}");
    EXPECT_NE(object.find("unknown texture type 'stars'"), std::string::npos) << object;
}

TEST(SceneReader, UnreadableTextureIsNamed) {
    const std::string e = errorOf(
        "{\"metric\": {\"name\": \"godel\"}, \"objects\": [{\"type\": \"sphere\", "
        "\"centre\": [0,1,0,0], \"radius\": 0.2, \"texture\": \"no-such.png\"}]}");
    EXPECT_NE(e.find("objects[0].texture"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot load texture"), std::string::npos) << e;
}

}  // namespace

namespace {

TEST(SceneReader, BoxesLightsAndMotionLoad) {
    const Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/sr_cube.json");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].triangles.size(), 6u * 2 * 10 * 10);  // 200 triangles per face
    EXPECT_EQ(s.meshes[0].motion.kind, Motion::Kind::ConstantVelocity);
    EXPECT_DOUBLE_EQ(s.meshes[0].motion.beta(0), 0.95);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_DOUBLE_EQ(s.lights[0].temperature, 6000);
    // Box normals point outwards: along the offset of each face's vertices.
    for (std::size_t i = 0; i < s.meshes[0].positions.size(); ++i)
        EXPECT_GT(s.meshes[0].normals[i].dot(s.meshes[0].positions[i]), 0);
}

TEST(SceneReader, SpeedOfLightAndBadMotionAreRejected) {
    const std::string base =
        "{\"metric\": {\"name\": \"minkowski\"}, \"objects\": [{\"type\": \"box\", \"centre\": [0,0,0,-5], "
        "\"size\": [1,1,1], \"motion\": ";
    EXPECT_NE(
        errorOf(base + "{\"type\": \"constant_velocity\", \"beta\": [0.8, 0.7, 0]}}]}").find("speed |beta| = 1.063"),
        std::string::npos);
    EXPECT_NE(errorOf(base + "{\"type\": \"free_fall\"}}]}").find("godel"), std::string::npos);
    EXPECT_NE(errorOf(base + "{\"type\": \"warp\"}}]}").find("unknown motion type"), std::string::npos);
    EXPECT_NE(
        errorOf("{\"metric\": {\"name\": \"minkowski\"}, \"objects\": [{\"type\": \"box\", \"centre\": [0,0,0,-5], "
                "\"size\": [1,-1,1]}]}")
            .find("objects[0].size[1]"),
        std::string::npos);
}

TEST(SceneReader, MeshFileNeedsALoaderAndTriangles) {
    const std::string scene =
        "{\"metric\": {\"name\": \"minkowski\"}, \"objects\": [{\"type\": \"mesh\", \"centre\": [0,0,0,-5], "
        "\"file\": \"thing.obj\"}]}";
    EXPECT_NE(errorOf(scene).find("built without a mesh reader"), std::string::npos);
    io::SceneReadOptions opt;
    opt.meshLoader = [](const std::string&, MeshObject&) {};  // reads nothing: an empty mesh
    try {
        io::parseScene(scene, "bad.json", ".", opt);
        FAIL();
    } catch (const io::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("has no triangles"), std::string::npos) << e.what();
    }
    opt.meshLoader = [](const std::string&, MeshObject&) { throw std::runtime_error("no such file"); };
    try {
        io::parseScene(scene, "bad.json", ".", opt);
        FAIL();
    } catch (const io::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[0].file"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
    }
}

TEST(SceneReader, FreeFallSpeedSetsTheEnergy) {
    const Scene s = io::parseScene(
        "{\"metric\": {\"name\": \"godel\"}, \"objects\": [{\"type\": \"sphere\", \"centre\": [0,1,0,0], "
        "\"radius\": 0.2, \"motion\": {\"type\": \"free_fall\", \"speed\": 0.6}}]}",
        "x.json");
    EXPECT_NEAR(s.spheres[0].motion.k0, 1.25, 1e-15);  // gamma(0.6)
}

}  // namespace

namespace {

TEST(SceneReader, AnimationBlockGivesThePathAndIsCheckedLikeTheRest) {
    const Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_free_fall_earth.json");
    ASSERT_TRUE(s.animation.properTime.has_value());
    EXPECT_EQ(s.animation.frames(), 48);
    EXPECT_DOUBLE_EQ(s.animation.properTime->at(47), 3);
    const std::string head = R"({"metric": {"name": "kerr"}, "observer": {"position": [0, 30, 0, 0]},
  "animation": )";
    const Scene swept = io::parseScene(head + R"({"frames": 5, "pan": [0, 90],
      "sweep": {"field": "metric.a", "from": 0, "to": 0.5}}})",
                                       "ok.json");
    EXPECT_EQ(swept.animation.sweep->field, "metric.a");
    EXPECT_DOUBLE_EQ(swept.animation.panDegrees->at(4), 90);
    struct Case {
        std::string block, message;
    };
    for (const Case& c : std::vector<Case>{
             {R"({"frames": 0, "pan": [0, 1]})", "field 'animation.frames': expected an integer in [1, 1e+05]"},
             {R"({"frames": 3})", "an animation needs a path"},
             {R"({"frames": 3, "motion": "static", "pan": [0, 1]})", "motion goes with proper_time"},
             {R"({"frames": 3, "proper_time": [0, 1], "motion": "hover"})", "unknown observer motion 'hover'"},
             {R"({"frames": 3, "pan": [0, 1e9]})", "animation.pan[1]"},
             {R"({"frames": 3, "zoom": [1, 2]})", "zoom"},
             {R"({"frames": 3, "sweep": {"field": "animation.frames", "from": 1, "to": 2}})",
              "cannot change the animation"},
         }) {
        const std::string e = errorOf(head + c.block + "}");
        EXPECT_NE(e.find(c.message), std::string::npos) << c.block << "\n" << e;
    }
}

}  // namespace

namespace {

TEST(SceneReader, TextureCacheSharesUnchangedImagesAndRereadsChangedOnes) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("lightcone-texture-cache-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // A 2x1 image: red, then green.
    io::ImageChannels img;
    img.width = 2;
    img.height = 1;
    img.names = {"R", "G", "B"};
    img.data = {1, 0, 0, 0, 1, 0};
    io::writeImage((dir / "t.exr").string(), img);
    const std::string scene = R"({"metric": {"name": "godel"},
        "objects": [{"type": "sphere", "centre": [0, 1, 0, 0], "radius": 0.2, "texture": "t.exr"}]})";
    io::SceneReadOptions options;
    options.textures = std::make_shared<io::TextureCache>();
    const Scene first = io::parseScene(scene, "a.json", dir.string(), options);
    const Scene second = io::parseScene(scene, "a.json", dir.string(), options);
    EXPECT_EQ(first.spheres[0].texture, second.spheres[0].texture);  // one image in memory
    EXPECT_NE(io::parseScene(scene, "a.json", dir.string()).spheres[0].texture, first.spheres[0].texture);
    // The file changes (new content, a later time): the next read loads it.
    img.data = {0, 0, 1, 0, 0, 1};
    io::writeImage((dir / "t.exr").string(), img);
    fs::last_write_time(dir / "t.exr", fs::last_write_time(dir / "t.exr") + std::chrono::seconds(2));
    const Scene third = io::parseScene(scene, "a.json", dir.string(), options);
    EXPECT_NE(third.spheres[0].texture, first.spheres[0].texture);
    EXPECT_NEAR(third.spheres[0].texture->sample(0.25, 0.5)(2), 1, 1e-6);  // blue now
    fs::remove_all(dir);
}

}  // namespace

namespace {

// look_at: forward is the chart direction from the observer to the point, resolved where the
// observer is (so it follows an observer that moves); a render with it equals one with that forward.
TEST(SceneReader, LookAtPointsForwardFromTheObserverToThePoint) {
    const std::string head = R"({"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 8, 3, 4]},
  "camera": {"width": 24, "height": 16, "fov": [80, 60], "up": [0, 0, 1], )";
    const Scene looking = io::parseScene(head + R"("look_at": [1, -1, 0.5]}})", "look.json");
    ASSERT_TRUE(looking.camera.lookAt.has_value());
    Scene pointed = io::parseScene(head + R"("forward": [-7, -4, -3.5]}})", "forward.json");
    Scene a = looking, b = pointed;
    a.settings.progress = b.settings.progress = false;
    const RenderResult ra = render(a), rb = render(b);
    ASSERT_EQ(ra.pixels.size(), rb.pixels.size());
    for (std::size_t n = 0; n < ra.pixels.size(); ++n) {
        EXPECT_EQ(ra.pixels[n].stopReason, rb.pixels[n].stopReason) << n;
        EXPECT_EQ(ra.pixels[n].u, rb.pixels[n].u) << n;
    }
    // Refused with the field named: both given, the observer's own position, along up.
    EXPECT_NE(errorOf(head + R"("forward": [1, 0, 0], "look_at": [0, 0, 0]}})").find("field 'camera.look_at': both"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"("look_at": [8, 3, 4]}})").find("field 'camera.look_at'"), std::string::npos);
    EXPECT_NE(errorOf(head + R"("look_at": [8, 3, 40]}})").find("point the same way"), std::string::npos);
}

}  // namespace
