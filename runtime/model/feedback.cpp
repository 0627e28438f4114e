#include "runtime/model/feedback.h"

#include <algorithm>
#include <cmath>

namespace ks::runtime::feedback {

namespace {
// Appends `item`, or replaces the oldest when full.
template <class T, std::size_t N>
void add(std::array<T, N>& items, std::size_t& count, const T& item) {
    if (count < N) {
        items[count++] = item;
        return;
    }
    auto oldest =
        std::max_element(items.begin(), items.end(), [](const T& a, const T& b) { return a.age < b.age; });
    *oldest = item;
}
} // namespace

std::optional<float> damage_arc_angle(float yaw, const Vec3& eye, const Vec3& source) {
    const Vec3 d = source - eye;
    const Vec3 forward(-std::sin(yaw), 0.0f, -std::cos(yaw));
    const Vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw));
    const float ahead = glm::dot(d, forward), aside = glm::dot(d, right);
    if (!is_finite(ahead) || !is_finite(aside) || ahead * ahead + aside * aside < 1e-4f) return std::nullopt;
    return std::atan2(aside, ahead);
}

float damage_arc_strength(float age) {
    if (!(age >= 0.0f) || age >= kDamageArcSeconds) return 0.0f;
    const float k = 1.0f - age / kDamageArcSeconds;
    return k * (1.5f - 0.5f * k); // slower than linear at first, so a hit reads for most of the second
}

float shake_strength(float distance, float radius) {
    if (!is_finite(distance) || !is_finite(radius)) return 0.0f;
    const float r = radius > 0.0f ? std::min(radius, 50.0f) : kRobotDeathShakeRadius;
    const float size = std::clamp(r / 7.0f, 0.3f, 1.5f);
    const float falloff = std::clamp(1.0f - std::max(distance, 0.0f) / (4.0f * r + 6.0f), 0.0f, 1.0f);
    return size * falloff * falloff;
}

float shake_envelope(float age) {
    if (!(age >= 0.0f) || age >= kShakeSeconds) return 0.0f;
    const float k = 1.0f - age / kShakeSeconds;
    return k * k;
}

ShakeAngles shake_offset(std::uint32_t seed, float age, float strength) {
    const float a = kShakeMaxRadians * std::clamp(strength, 0.0f, 2.0f) * shake_envelope(age);
    if (!(a > 0.0f)) return {};
    std::uint32_t state = seed * 2654435761u + 0x9e3779b9u;
    auto next = [&state] { // xorshift32: a fraction in [0, 1)
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    auto wave = [&](float low_hz, float high_hz) {
        const float f1 = low_hz * (0.85f + 0.3f * next()), f2 = high_hz * (0.85f + 0.3f * next());
        const float p1 = 2.0f * kPi * next(), p2 = 2.0f * kPi * next();
        return 0.65f * std::sin(2.0f * kPi * f1 * age + p1) + 0.35f * std::sin(2.0f * kPi * f2 * age + p2);
    };
    ShakeAngles s;
    s.yaw = a * wave(11.0f, 19.0f);
    s.pitch = a * wave(13.0f, 23.0f);
    s.roll = 0.5f * a * wave(7.0f, 17.0f);
    return s;
}

Vec3 hit_tint(float flash_left) {
    const float k =
        std::clamp(is_finite(flash_left) ? flash_left / game::kRobotHitFlashSeconds : 0.0f, 0.0f, 1.0f);
    return Vec3(1.0f, 0.0f, 0.0f) * (0.9f * k * k);
}

float muzzle_light_intensity(float age) {
    if (!(age >= 0.0f) || age >= kMuzzleLightSeconds) return 0.0f;
    return 3.0f * (1.0f - age / kMuzzleLightSeconds);
}

MuzzleLight muzzle_light(const Vec3& position, float age, bool robot) {
    MuzzleLight l;
    l.position = position;
    l.color = robot ? Vec3(1.0f, 0.45f, 0.25f) : Vec3(1.0f, 0.72f, 0.4f);
    l.intensity = muzzle_light_intensity(age);
    l.range = robot ? 6.0f : 7.0f;
    return l;
}

void Feedback::update(float dt) {
    if (!(dt > 0.0f)) return;
    auto age = [dt](auto& items, std::size_t& count, float limit) {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < count; ++i) {
            items[i].age += dt;
            if (items[i].age < limit) items[kept++] = items[i];
        }
        count = kept;
    };
    age(arcs_, arc_count_, kDamageArcSeconds);
    age(shakes_, shake_count_, kShakeSeconds);
    age(lights_, light_count_, kMuzzleLightSeconds);
}

void Feedback::on_event(const game::Event& e, const Vec3& eye) {
    using game::EventType;
    switch (e.type) {
    case EventType::PlayerDamaged:
        // position = the source, end = the eye at the hit; the same point: no direction (a fall).
        if (glm::length(e.position - e.end) > 1e-3f) add_arc(e.position, eye);
        break;
    case EventType::Explosion: {
        const float strength = shake_strength(glm::length(e.position - eye), e.amount);
        if (strength > 0.0f)
            add(shakes_, shake_count_,
                Shake{next_seed_++ ^ static_cast<std::uint32_t>(e.entity), strength, 0.0f});
        break;
    }
    case EventType::ShotFired:
    case EventType::RobotShot:
        add(lights_, light_count_, Flash{e.position, e.type == EventType::RobotShot, 0.0f});
        break;
    default:
        break;
    }
}

std::size_t Feedback::damage_arcs(float yaw, const Vec3& eye, std::array<DamageArc, kMaxArcs>& out) const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < arc_count_; ++i) {
        const auto angle = damage_arc_angle(yaw, eye, arcs_[i].source);
        const float strength = damage_arc_strength(arcs_[i].age);
        if (angle && strength > 0.0f) out[n++] = {*angle, strength};
    }
    return n;
}

ShakeAngles Feedback::shake(float extra) const {
    ShakeAngles sum;
    for (std::size_t i = 0; i < shake_count_; ++i) {
        const ShakeAngles s = shake_offset(shakes_[i].seed, shakes_[i].age + extra, shakes_[i].strength);
        sum.yaw += s.yaw;
        sum.pitch += s.pitch;
        sum.roll += s.roll;
    }
    return sum;
}

std::size_t Feedback::muzzle_lights(std::array<MuzzleLight, kMaxLights>& out, float extra) const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < light_count_; ++i)
        if (muzzle_light_intensity(lights_[i].age + extra) > 0.0f)
            out[n++] = muzzle_light(lights_[i].position, lights_[i].age + extra, lights_[i].robot);
    return n;
}

void Feedback::add_arc(const Vec3& source, const Vec3& eye) {
    const auto bearing = damage_arc_angle(0.0f, eye, source);
    if (!bearing) return;
    for (std::size_t i = 0; i < arc_count_; ++i) {
        const auto other = damage_arc_angle(0.0f, eye, arcs_[i].source);
        if (other && std::abs(std::remainder(*other - *bearing, 2.0f * kPi)) < 0.25f) {
            arcs_[i] = {source, 0.0f};
            return;
        }
    }
    add(arcs_, arc_count_, Arc{source, 0.0f});
}

} // namespace ks::runtime::feedback
