#include "anim/easing.h"

#include <algorithm>
#include <cmath>

namespace ks::anim {
namespace {

double power_in(double k, double p) {
    return std::pow(k, p);
}

double power_curve(EaseMode mode, double k, double p) {
    switch (mode) {
    case EaseMode::In:
        return power_in(k, p);
    case EaseMode::Out:
        return 1.0 - power_in(1.0 - k, p);
    case EaseMode::InOut:
        return k < 0.5 ? 0.5 * power_in(2.0 * k, p) : 1.0 - 0.5 * power_in(2.0 - 2.0 * k, p);
    }
    return k;
}

// CSS cubic-bezier: x(s) and y(s) for P0 = (0,0), P1, P2, P3 = (1,1). x is monotonic in s because x1 and x2
// lie in [0, 1], so x(s) = k has exactly one root: Newton from s = k, falling back to bisection.
double bezier_coord(double s, double p1, double p2) {
    double u = 1.0 - s;
    return 3.0 * u * u * s * p1 + 3.0 * u * s * s * p2 + s * s * s;
}
double bezier_slope(double s, double p1, double p2) {
    double u = 1.0 - s;
    return 3.0 * u * u * p1 + 6.0 * u * s * (p2 - p1) + 3.0 * s * s * (1.0 - p2);
}
double bezier_curve(const std::array<float, 4>& c, double k) {
    const double x1 = c[0], y1 = c[1], x2 = c[2], y2 = c[3];
    double s = k;
    for (int i = 0; i < 8; ++i) {
        double err = bezier_coord(s, x1, x2) - k;
        if (std::abs(err) < 1e-12) return bezier_coord(s, y1, y2);
        double slope = bezier_slope(s, x1, x2);
        if (std::abs(slope) < 1e-9) break;
        s = std::clamp(s - err / slope, 0.0, 1.0);
    }
    double lo = 0.0, hi = 1.0;
    s = k;
    for (int i = 0; i < 60; ++i) {
        double x = bezier_coord(s, x1, x2);
        if (std::abs(x - k) < 1e-13) break;
        (x < k ? lo : hi) = s;
        s = 0.5 * (lo + hi);
    }
    return bezier_coord(s, y1, y2);
}

struct FamilyName {
    EaseFamily family;
    const char* name;
};
constexpr FamilyName kFamilies[] = {
    {EaseFamily::Linear, "Linear"},
    {EaseFamily::Quadratic, "Quadratic"},
    {EaseFamily::Cubic, "Cubic"},
    {EaseFamily::Quartic, "Quartic"},
    {EaseFamily::Quintic, "Quintic"},
    {EaseFamily::Sinusoidal, "Sinusoidal"},
    {EaseFamily::Exponential, "Exponential"},
    {EaseFamily::Circular, "Circular"},
    {EaseFamily::Elastic, "Elastic"},
    {EaseFamily::Back, "Back"},
    {EaseFamily::Bounce, "Bounce"},
};
constexpr const char* kModeNames[] = {"In", "Out", "InOut"};

} // namespace

double Ease::operator()(double t) const {
    // Exact endpoints for every curve: Tween.js's own formulas miss them by rounding (1 - cos(pi/2) != 1 in
    // floating point; Back.Out(1) = 1 + 1e-16), and a clip must land exactly on its key values.
    if (!(t > 0.0)) return 0.0; // also maps NaN to 0
    if (t >= 1.0) return 1.0;
    switch (family) {
    case EaseFamily::Power:
        return power_curve(mode, t, params[0]);
    case EaseFamily::CubicBezier:
        return bezier_curve(params, t);
    default:
        return tweenjs_formula(family, mode, t);
    }
}

double Ease::derivative(double t) const {
    if (family == EaseFamily::Linear) return 1.0;
    t = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0);
    constexpr double h = 1e-6;
    double lo = std::max(0.0, t - h), hi = std::min(1.0, t + h);
    return ((*this)(hi) - (*this)(lo)) / (hi - lo);
}

std::string ease_name(const Ease& ease) {
    if (ease.family == EaseFamily::Linear) return "Linear.None";
    for (const auto& f : kFamilies)
        if (f.family == ease.family)
            return std::string(f.name) + "." + kModeNames[static_cast<int>(ease.mode)];
    return {};
}

std::optional<Ease> parse_ease_name(std::string_view name) {
    if (name == "Linear" || name == "Linear.None") return Ease::linear();
    auto dot = name.find('.');
    if (dot == std::string_view::npos) return std::nullopt;
    std::string_view family = name.substr(0, dot), mode = name.substr(dot + 1);
    for (const auto& f : kFamilies) {
        if (f.family == EaseFamily::Linear || family != f.name) continue;
        for (int m = 0; m < 3; ++m)
            if (mode == kModeNames[m]) return Ease::named(f.family, static_cast<EaseMode>(m));
    }
    return std::nullopt;
}

const std::vector<std::string>& known_ease_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out{"Linear.None"};
        for (const auto& f : kFamilies) {
            if (f.family == EaseFamily::Linear) continue;
            for (const char* m : kModeNames) out.push_back(std::string(f.name) + "." + m);
        }
        return out;
    }();
    return names;
}

std::string validate_ease(const Ease& ease) {
    for (float p : ease.params)
        if (!std::isfinite(p)) return "ease parameters must be finite numbers";
    if (ease.family == EaseFamily::Power && !(ease.params[0] > 0.0f && ease.params[0] <= 64.0f))
        return "power exponent must be in (0, 64]";
    if (ease.family == EaseFamily::CubicBezier &&
        !(ease.params[0] >= 0 && ease.params[0] <= 1 && ease.params[2] >= 0 && ease.params[2] <= 1))
        return "cubic Bezier x1 and x2 must be in [0, 1] (so time runs forward)";
    return {};
}

} // namespace ks::anim
