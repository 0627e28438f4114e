#include "anim/easing.h"

#include <cmath>
#include <doctest/doctest.h>
#include <string>

using namespace ks::anim;

namespace {
double ease(const char* name, double t) {
    auto e = parse_ease_name(name);
    REQUIRE_MESSAGE(e.has_value(), name);
    return (*e)(t);
}
} // namespace

TEST_CASE("every Tween.js family and mode is known, and names round-trip") {
    const auto& names = known_ease_names();
    CHECK(names.size() == 1 + 10 * 3); // Linear.None + ten families x In/Out/InOut
    for (const std::string& name : names) {
        auto e = parse_ease_name(name);
        REQUIRE_MESSAGE(e.has_value(), name);
        CHECK(ease_name(*e) == name);
    }
    CHECK(parse_ease_name("Linear").has_value());
    CHECK_FALSE(parse_ease_name("Quadratic.Inn").has_value());
    CHECK_FALSE(parse_ease_name("Quadratic").has_value());
    CHECK_FALSE(parse_ease_name("").has_value());
    CHECK_FALSE(parse_ease_name("Linear.In").has_value());
}

TEST_CASE("exact endpoints and no NaN on [0, 1] for every curve") {
    std::vector<Ease> curves;
    for (const std::string& name : known_ease_names()) curves.push_back(*parse_ease_name(name));
    for (float p : {0.3f, 1.0f, 2.5f, 7.0f})
        for (EaseMode m : {EaseMode::In, EaseMode::Out, EaseMode::InOut}) curves.push_back(Ease::power(p, m));
    curves.push_back(Ease::bezier(0.25f, 0.1f, 0.25f, 1.0f));
    curves.push_back(Ease::bezier(0.0f, 0.0f, 1.0f, 1.0f));
    curves.push_back(Ease::bezier(0.0f, 1.5f, 1.0f, -0.5f)); // overshooting y
    curves.push_back(Ease::bezier(1.0f, 0.0f, 0.0f, 1.0f));  // flat slope in the middle
    for (const Ease& e : curves) {
        INFO(ease_name(e), " family ", int(e.family), " mode ", int(e.mode));
        CHECK(e(0.0) == 0.0);
        CHECK(e(1.0) == 1.0);
        CHECK(e(-1.0) == 0.0);
        CHECK(e(2.0) == 1.0);
        CHECK(e(std::nan("")) == 0.0);
        for (int i = 0; i <= 10000; ++i) {
            double v = e(i / 10000.0);
            REQUIRE(std::isfinite(v));
            REQUIRE(std::abs(v) < 3.0); // Back and Elastic overshoot, but boundedly
            REQUIRE(std::isfinite(e.derivative(i / 10000.0)));
        }
    }
}

TEST_CASE("values match the Tween.js closed forms at sample points") {
    const double eps = 1e-12;
    CHECK(ease("Linear.None", 0.3) == doctest::Approx(0.3).epsilon(eps));
    CHECK(ease("Quadratic.In", 0.5) == doctest::Approx(0.25).epsilon(eps));
    CHECK(ease("Quadratic.Out", 0.5) == doctest::Approx(0.75).epsilon(eps));
    CHECK(ease("Quadratic.InOut", 0.25) == doctest::Approx(0.125).epsilon(eps));
    CHECK(ease("Quadratic.InOut", 0.75) == doctest::Approx(0.875).epsilon(eps));
    CHECK(ease("Cubic.In", 0.5) == doctest::Approx(0.125).epsilon(eps));
    CHECK(ease("Cubic.Out", 0.5) == doctest::Approx(0.875).epsilon(eps));
    CHECK(ease("Cubic.InOut", 0.25) == doctest::Approx(0.0625).epsilon(eps));
    CHECK(ease("Quartic.In", 0.5) == doctest::Approx(0.0625).epsilon(eps));
    CHECK(ease("Quartic.Out", 0.5) == doctest::Approx(0.9375).epsilon(eps));
    CHECK(ease("Quartic.InOut", 0.75) == doctest::Approx(0.96875).epsilon(eps));
    CHECK(ease("Quintic.In", 0.5) == doctest::Approx(0.03125).epsilon(eps));
    CHECK(ease("Quintic.Out", 0.5) == doctest::Approx(0.96875).epsilon(eps));
    CHECK(ease("Quintic.InOut", 0.25) == doctest::Approx(0.015625).epsilon(eps));
    CHECK(ease("Sinusoidal.In", 0.5) == doctest::Approx(1 - std::sqrt(0.5)).epsilon(eps));
    CHECK(ease("Sinusoidal.Out", 0.5) == doctest::Approx(std::sqrt(0.5)).epsilon(eps));
    CHECK(ease("Sinusoidal.InOut", 0.25) == doctest::Approx(0.5 * (1 - std::sqrt(0.5))).epsilon(eps));
    CHECK(ease("Exponential.In", 0.5) == doctest::Approx(0.03125).epsilon(eps));  // 1024^-0.5
    CHECK(ease("Exponential.Out", 0.5) == doctest::Approx(0.96875).epsilon(eps)); // 1 - 2^-5
    CHECK(ease("Exponential.InOut", 0.25) == doctest::Approx(0.015625).epsilon(eps));
    CHECK(ease("Circular.In", 0.5) == doctest::Approx(1 - std::sqrt(0.75)).epsilon(eps));
    CHECK(ease("Circular.Out", 0.5) == doctest::Approx(std::sqrt(0.75)).epsilon(eps));
    CHECK(ease("Circular.InOut", 0.25) == doctest::Approx(0.5 * (1 - std::sqrt(0.75))).epsilon(eps));
    // Elastic (Tween.js 16+): Out(0.25) = 2^-2.5 sin(0.75 pi) + 1 = 1.125; In(0.75) = -0.125.
    CHECK(ease("Elastic.Out", 0.25) == doctest::Approx(1.125).epsilon(eps));
    CHECK(ease("Elastic.In", 0.75) == doctest::Approx(-0.125).epsilon(eps));
    CHECK(ease("Elastic.InOut", 0.375) == doctest::Approx(-0.0625).epsilon(eps));
    // Back: s = 1.70158 (and 1.70158 * 1.525 for InOut).
    CHECK(ease("Back.In", 0.5) == doctest::Approx(0.25 * (2.70158 * 0.5 - 1.70158)).epsilon(eps));
    CHECK(ease("Back.Out", 0.5) == doctest::Approx(1 - 0.25 * (2.70158 * 0.5 - 1.70158)).epsilon(eps));
    const double s = 1.70158 * 1.525;
    CHECK(ease("Back.InOut", 0.25) == doctest::Approx(0.5 * 0.25 * ((s + 1) * 0.5 - s)).epsilon(eps));
    // Bounce: the four parabolas with 7.5625 and 2.75.
    CHECK(ease("Bounce.Out", 0.2) == doctest::Approx(7.5625 * 0.04).epsilon(eps));
    CHECK(ease("Bounce.Out", 0.5) == doctest::Approx(0.765625).epsilon(eps));
    CHECK(ease("Bounce.Out", 0.8) ==
          doctest::Approx(7.5625 * std::pow(0.8 - 2.25 / 2.75, 2) + 0.9375).epsilon(eps));
    CHECK(ease("Bounce.Out", 0.95) ==
          doctest::Approx(7.5625 * std::pow(0.95 - 2.625 / 2.75, 2) + 0.984375).epsilon(eps));
    CHECK(ease("Bounce.In", 0.5) == doctest::Approx(0.234375).epsilon(eps));
    CHECK(ease("Bounce.InOut", 0.25) == doctest::Approx(0.1171875).epsilon(eps));
    CHECK(ease("Bounce.InOut", 0.75) == doctest::Approx(0.8828125).epsilon(eps));
}

TEST_CASE("Out is the mirror of In, and InOut is In then Out, for every named family") {
    // Except Back.InOut, which Tween.js gives a larger overshoot (s * 1.525) than Back.In/Out: checked below.
    for (int f = 1; f <= static_cast<int>(EaseFamily::Bounce); ++f) {
        const auto family = static_cast<EaseFamily>(f);
        Ease in = Ease::named(family, EaseMode::In), out = Ease::named(family, EaseMode::Out);
        Ease inout = Ease::named(family, EaseMode::InOut);
        INFO(ease_name(in));
        for (int i = 1; i < 20; ++i) {
            const double t = i / 20.0;
            CHECK(out(t) == doctest::Approx(1 - in(1 - t)).epsilon(1e-9));
            if (family == EaseFamily::Back) continue;
            if (t < 0.5) CHECK(inout(t) == doctest::Approx(0.5 * in(2 * t)).epsilon(1e-9));
            if (t > 0.5) CHECK(inout(t) == doctest::Approx(0.5 + 0.5 * out(2 * t - 1)).epsilon(1e-9));
        }
    }
}

TEST_CASE("custom power and cubic Bezier curves") {
    for (double t = 0.0; t <= 1.0; t += 0.0625) {
        CHECK(Ease::power(2, EaseMode::In)(t) == doctest::Approx(ease("Quadratic.In", t)).epsilon(1e-12));
        CHECK(Ease::power(3, EaseMode::InOut)(t) == doctest::Approx(ease("Cubic.InOut", t)).epsilon(1e-12));
        CHECK(Ease::power(5, EaseMode::Out)(t) == doctest::Approx(ease("Quintic.Out", t)).epsilon(1e-12));
        CHECK(Ease::bezier(0, 0, 1, 1)(t) == doctest::Approx(t).epsilon(1e-9));
    }
    // CSS "ease" = cubic-bezier(0.25, 0.1, 0.25, 1): y(0.5) = 0.8024033877 (browsers' reference value).
    CHECK(Ease::bezier(0.25f, 0.1f, 0.25f, 1.0f)(0.5) == doctest::Approx(0.8024033877).epsilon(1e-6));
    // CSS ease-in-out is symmetric.
    Ease in_out = Ease::bezier(0.42f, 0, 0.58f, 1);
    CHECK(in_out(0.5) == doctest::Approx(0.5).epsilon(1e-7));
    CHECK(in_out(0.2) == doctest::Approx(1 - in_out(0.8)).epsilon(1e-6));
    // Monotone when the y control points lie in [0, 1].
    double prev = 0;
    for (int i = 1; i <= 1000; ++i) {
        double v = in_out(i / 1000.0);
        CHECK(v >= prev);
        prev = v;
    }
    CHECK(validate_ease(Ease::bezier(1.5f, 0, 0.5f, 1)).find("x1 and x2") != std::string::npos);
    CHECK(validate_ease(Ease::power(0, EaseMode::In)).find("exponent") != std::string::npos);
    CHECK(validate_ease(Ease::power(NAN, EaseMode::In)).find("finite") != std::string::npos);
    CHECK(validate_ease(Ease::power(2, EaseMode::In)).empty());
}

TEST_CASE("derivatives match the analytic ones") {
    CHECK(Ease::linear().derivative(0.3) == 1.0);
    CHECK(ease_name(Ease::named(EaseFamily::Quadratic, EaseMode::In)) == "Quadratic.In");
    const Ease quad_in = Ease::named(EaseFamily::Quadratic, EaseMode::In);
    const Ease sine_io = Ease::named(EaseFamily::Sinusoidal, EaseMode::InOut);
    for (int i = 1; i < 10; ++i) {
        const double t = i / 10.0;
        CHECK(quad_in.derivative(t) == doctest::Approx(2 * t).epsilon(1e-6));
        CHECK(sine_io.derivative(t) == doctest::Approx(0.5 * M_PI * std::sin(M_PI * t)).epsilon(1e-6));
    }
    CHECK(quad_in.derivative(0.0) == doctest::Approx(0.0).epsilon(1e-5));
    CHECK(quad_in.derivative(1.0) == doctest::Approx(2.0).epsilon(1e-5));
}
