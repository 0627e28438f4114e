#pragma once
// Easing curves: every Tween.js (16.x-18.x) family with the library's exact formulas and constants, plus a
// custom power curve and a CSS-style cubic Bezier. An Ease is a small value (no allocation, no virtuals) so
// clip keys can hold one each.
//
// Guarantees (tested): f(0) = 0 and f(1) = 1 exactly for every curve, no NaN for any input (inputs outside
// [0, 1] are clamped), values equal the Tween.js closed forms at interior points.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::anim {

enum class EaseFamily : std::uint8_t {
    Linear,
    Quadratic,
    Cubic,
    Quartic,
    Quintic,
    Sinusoidal,
    Exponential,
    Circular,
    Elastic,
    Back,
    Bounce,
    Power,       // custom: t^p (param[0] = p > 0)
    CubicBezier, // custom: CSS cubic-bezier(x1, y1, x2, y2), x1 and x2 in [0, 1]
};

enum class EaseMode : std::uint8_t { In, Out, InOut };

struct Ease {
    EaseFamily family = EaseFamily::Linear;
    EaseMode mode = EaseMode::In;  // ignored by Linear and CubicBezier
    std::array<float, 4> params{}; // Power: {p}; CubicBezier: {x1, y1, x2, y2}

    static Ease linear() { return {}; }
    static Ease named(EaseFamily family, EaseMode mode) { return {family, mode, {}}; }
    static Ease power(float exponent, EaseMode mode) {
        return {EaseFamily::Power, mode, {exponent, 0, 0, 0}};
    }
    static Ease bezier(float x1, float y1, float x2, float y2) {
        return {EaseFamily::CubicBezier, EaseMode::In, {x1, y1, x2, y2}};
    }

    // The eased progress for t in [0, 1] (clamped outside).
    double operator()(double t) const;
    // d/dt of the eased progress, for velocity-continuous blending (one-sided at the ends).
    double derivative(double t) const;

    bool operator==(const Ease&) const = default;
};

// The Tween.js name of a named curve: "Linear.None", "Quadratic.In", "Bounce.InOut", ... Custom curves have
// no name (empty string).
std::string ease_name(const Ease& ease);
// Parses a Tween.js name ("Linear" and "Linear.None" both accepted). nullopt for unknown names.
std::optional<Ease> parse_ease_name(std::string_view name);
// Every accepted name, in family order, for error hints and editor menus.
const std::vector<std::string>& known_ease_names();

// Why a custom curve's parameters are invalid, or empty if they are fine (exponent > 0 and finite; Bezier x
// control points in [0, 1], all finite).
std::string validate_ease(const Ease& ease);

// The Tween.js formula itself, without the endpoint guarantee (tests compare against it).
double tweenjs_formula(EaseFamily family, EaseMode mode, double k);

} // namespace ks::anim
