// The Tween.js easing formulas, one function per family, written as the library writes them (the in-place
// updates of k included) so the values match it to the last bit.
#include "anim/easing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ks::anim {
namespace {

constexpr double kPi = std::numbers::pi;

double quadratic(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return k * k;
    case EaseMode::Out:
        return k * (2 - k);
    case EaseMode::InOut:
        if ((k *= 2) < 1) return 0.5 * k * k;
        --k;
        return -0.5 * (k * (k - 2) - 1);
    }
    return k;
}

double cubic(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return k * k * k;
    case EaseMode::Out:
        --k;
        return k * k * k + 1;
    case EaseMode::InOut:
        if ((k *= 2) < 1) return 0.5 * k * k * k;
        k -= 2;
        return 0.5 * (k * k * k + 2);
    }
    return k;
}

double quartic(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return k * k * k * k;
    case EaseMode::Out:
        --k;
        return 1 - k * k * k * k;
    case EaseMode::InOut:
        if ((k *= 2) < 1) return 0.5 * k * k * k * k;
        k -= 2;
        return -0.5 * (k * k * k * k - 2);
    }
    return k;
}

double quintic(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return k * k * k * k * k;
    case EaseMode::Out:
        --k;
        return k * k * k * k * k + 1;
    case EaseMode::InOut:
        if ((k *= 2) < 1) return 0.5 * k * k * k * k * k;
        k -= 2;
        return 0.5 * (k * k * k * k * k + 2);
    }
    return k;
}

double sinusoidal(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return 1 - std::cos(k * kPi / 2);
    case EaseMode::Out:
        return std::sin(k * kPi / 2);
    case EaseMode::InOut:
        return 0.5 * (1 - std::cos(kPi * k));
    }
    return k;
}

double exponential(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return k == 0 ? 0 : std::pow(1024.0, k - 1);
    case EaseMode::Out:
        return k == 1 ? 1 : 1 - std::pow(2.0, -10 * k);
    case EaseMode::InOut:
        if (k == 0) return 0;
        if (k == 1) return 1;
        if ((k *= 2) < 1) return 0.5 * std::pow(1024.0, k - 1);
        return 0.5 * (-std::pow(2.0, -10 * (k - 1)) + 2);
    }
    return k;
}

double circular(EaseMode mode, double k) {
    // max(0, .) only guards rounding for k a hair outside [0, 1]; inside it the radicand is >= 0.
    switch (mode) {
    case EaseMode::In:
        return 1 - std::sqrt(std::max(0.0, 1 - k * k));
    case EaseMode::Out:
        --k;
        return std::sqrt(std::max(0.0, 1 - k * k));
    case EaseMode::InOut:
        if ((k *= 2) < 1) return -0.5 * (std::sqrt(std::max(0.0, 1 - k * k)) - 1);
        k -= 2;
        return 0.5 * (std::sqrt(std::max(0.0, 1 - k * k)) + 1);
    }
    return k;
}

// Tween.js 16+ form (fixed amplitude 1, period 0.4).
double elastic(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        if (k == 0) return 0;
        if (k == 1) return 1;
        return -std::pow(2.0, 10 * (k - 1)) * std::sin((k - 1.1) * 5 * kPi);
    case EaseMode::Out:
        if (k == 0) return 0;
        if (k == 1) return 1;
        return std::pow(2.0, -10 * k) * std::sin((k - 0.1) * 5 * kPi) + 1;
    case EaseMode::InOut:
        if (k == 0) return 0;
        if (k == 1) return 1;
        k *= 2;
        if (k < 1) return -0.5 * std::pow(2.0, 10 * (k - 1)) * std::sin((k - 1.1) * 5 * kPi);
        return 0.5 * std::pow(2.0, -10 * (k - 1)) * std::sin((k - 1.1) * 5 * kPi) + 1;
    }
    return k;
}

double back(EaseMode mode, double k) {
    double s = 1.70158;
    switch (mode) {
    case EaseMode::In:
        return k * k * ((s + 1) * k - s);
    case EaseMode::Out:
        --k;
        return k * k * ((s + 1) * k + s) + 1;
    case EaseMode::InOut:
        s *= 1.525;
        if ((k *= 2) < 1) return 0.5 * (k * k * ((s + 1) * k - s));
        k -= 2;
        return 0.5 * (k * k * ((s + 1) * k + s) + 2);
    }
    return k;
}

// Tween.js Bounce.Out (the In and InOut forms are built from it, as in the library).
double bounce_out(double k) {
    if (k < 1 / 2.75) return 7.5625 * k * k;
    if (k < 2 / 2.75) {
        k -= 1.5 / 2.75;
        return 7.5625 * k * k + 0.75;
    }
    if (k < 2.5 / 2.75) {
        k -= 2.25 / 2.75;
        return 7.5625 * k * k + 0.9375;
    }
    k -= 2.625 / 2.75;
    return 7.5625 * k * k + 0.984375;
}

double bounce(EaseMode mode, double k) {
    switch (mode) {
    case EaseMode::In:
        return 1 - bounce_out(1 - k);
    case EaseMode::Out:
        return bounce_out(k);
    case EaseMode::InOut:
        if (k < 0.5) return (1 - bounce_out(1 - k * 2)) * 0.5;
        return bounce_out(k * 2 - 1) * 0.5 + 0.5;
    }
    return k;
}

} // namespace

double tweenjs_formula(EaseFamily family, EaseMode mode, double k) {
    switch (family) {
    case EaseFamily::Linear:
        return k;
    case EaseFamily::Quadratic:
        return quadratic(mode, k);
    case EaseFamily::Cubic:
        return cubic(mode, k);
    case EaseFamily::Quartic:
        return quartic(mode, k);
    case EaseFamily::Quintic:
        return quintic(mode, k);
    case EaseFamily::Sinusoidal:
        return sinusoidal(mode, k);
    case EaseFamily::Exponential:
        return exponential(mode, k);
    case EaseFamily::Circular:
        return circular(mode, k);
    case EaseFamily::Elastic:
        return elastic(mode, k);
    case EaseFamily::Back:
        return back(mode, k);
    case EaseFamily::Bounce:
        return bounce(mode, k);
    case EaseFamily::Power:
    case EaseFamily::CubicBezier:
        break; // parameterised: not Tween.js curves
    }
    return k;
}

} // namespace ks::anim
