#include "anim/player.h"

#include "anim/rotation.h"

#include <cmath>

namespace ks::anim {
namespace {

Vec3 resolve(const Key& key, const Vec3& start) {
    return key.mode == KeyMode::Absolute ? key.value : start + key.value;
}

Vec3 wrap_angles(const Vec3& e) {
    return Vec3(wrap_angle(e.x), wrap_angle(e.y), wrap_angle(e.z));
}

template <class T>
void copy_into(std::span<const T> from, std::span<T> to) {
    for (std::size_t i = 0; i < to.size() && i < from.size(); ++i) to[i] = from[i];
}

} // namespace

std::int64_t to_flicks(double seconds) {
    if (!std::isfinite(seconds)) return 0;
    return std::llround(seconds * static_cast<double>(kFlicksPerSecond));
}

void sample_clip(const Clip& clip, std::span<const Vec3> start_euler, std::span<const Vec3> start_position,
                 double t, std::span<Vec3> out_euler, std::span<Vec3> out_position,
                 std::span<Vec3> velocity_euler, std::span<Vec3> velocity_position) {
    copy_into(start_euler, out_euler);
    copy_into(start_position, out_position);
    const bool want_velocity = !velocity_euler.empty();
    if (want_velocity) {
        for (Vec3& v : velocity_euler) v = Vec3(0);
        for (Vec3& v : velocity_position) v = Vec3(0);
    }
    if (!(t > 0)) t = 0;
    const double duration = clip.duration;
    double local = t;
    long long iteration = 0;
    float direction = 1; // -1 on a ping-pong clip's way back: the pose retraces, so its rate flips
    if (clip.loop == LoopMode::Loop && duration > 0) {
        iteration = static_cast<long long>(std::floor(t / duration));
        local = t - static_cast<double>(iteration) * duration;
    } else if (clip.loop == LoopMode::PingPong && duration > 0) {
        // Each cycle (2d) starts from the same start pose, so no iteration offset: t and 2d - t are equal.
        const double cycle = 2 * duration;
        local = t - std::floor(t / cycle) * cycle;
        if (local > duration) {
            local = cycle - local;
            direction = -1;
        }
    } else if (local > duration) {
        local = duration;
    }

    for (const Channel& ch : clip.channels) {
        const auto node = static_cast<std::size_t>(ch.node);
        const Key* keys = clip.keys.data() + ch.first_key;
        Vec3 start = ch.is_position ? start_position[node] : start_euler[node];
        if (iteration > 0) { // a loop iteration starts where the previous one ended
            const Key& last = keys[ch.key_count - 1];
            start = last.mode == KeyMode::Absolute ? last.value
                                                   : start + last.value * static_cast<float>(iteration);
        }
        Vec3 value, rate(0);
        std::uint32_t k = 1;
        while (k < ch.key_count && !(keys[k].time > local)) ++k;
        if (k >= ch.key_count) {
            value = resolve(keys[ch.key_count - 1], start);
        } else {
            const Key& k0 = keys[k - 1];
            const Key& k1 = keys[k];
            const Vec3 a = resolve(k0, start), b = resolve(k1, start);
            const double span = k1.time - k0.time;
            const double u = (local - k0.time) / span;
            value = a + (b - a) * static_cast<float>(k1.ease(u));
            if (want_velocity) rate = (b - a) * static_cast<float>(direction * k1.ease.derivative(u) / span);
        }
        (ch.is_position ? out_position : out_euler)[node] = value;
        if (want_velocity) (ch.is_position ? velocity_position : velocity_euler)[node] = rate;
    }
}

Player::Player(const ClipSet& clips, const Rig& rig) : clips_(clips), rig_(rig) {
    const auto n = static_cast<std::size_t>(rig.size());
    for (Instance* inst : {&current_, &fading_}) {
        inst->start_euler.resize(n);
        inst->start_position.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            inst->start_euler[i] = rig.node(static_cast<int>(i)).rest_euler;
            inst->start_position[i] = rig.node(static_cast<int>(i)).rest_position;
        }
    }
    for (auto* v : {&inertial_euler_, &inertial_position_, &inertial_vel_euler_, &inertial_vel_position_,
                    &a_euler_, &a_position_, &a_vel_euler_, &a_vel_position_, &b_euler_, &b_position_,
                    &b_vel_euler_, &b_vel_position_})
        v->assign(n, Vec3(0));
    pose_.set_rest(rig);
    fired_.reserve(16);
}

void Player::sample_instance(const Instance& inst, std::span<Vec3> euler, std::span<Vec3> position,
                             std::span<Vec3> vel_euler, std::span<Vec3> vel_position) const {
    if (inst.clip < 0) { // nothing playing: hold the start pose
        copy_into<Vec3>(inst.start_euler, euler);
        copy_into<Vec3>(inst.start_position, position);
        for (Vec3& v : vel_euler) v = Vec3(0);
        for (Vec3& v : vel_position) v = Vec3(0);
        return;
    }
    sample_clip(clips_.clips[static_cast<std::size_t>(inst.clip)], inst.start_euler, inst.start_position,
                to_seconds(now_ - inst.start), euler, position, vel_euler, vel_position);
}

void Player::evaluate(std::span<Vec3> euler, std::span<Vec3> position, std::span<Vec3> vel_euler,
                      std::span<Vec3> vel_position) {
    const bool want_velocity = !vel_euler.empty();
    sample_instance(current_, euler, position, vel_euler, vel_position);
    if (!blending()) return;

    // The source the output blends away from: an inertial continuation or the old clip still running.
    const double tau = to_seconds(now_ - blend_start_), length = to_seconds(blend_length_);
    std::span<Vec3> src_e = b_euler_, src_p = b_position_;
    std::span<Vec3> src_ve = want_velocity ? std::span<Vec3>(b_vel_euler_) : std::span<Vec3>();
    std::span<Vec3> src_vp = want_velocity ? std::span<Vec3>(b_vel_position_) : std::span<Vec3>();
    if (source_ == Source::Crossfade) {
        sample_instance(fading_, src_e, src_p, src_ve, src_vp);
    } else {
        // p(tau) = p0 + v0 (tau - tau^2 / 2L): velocity v0 (1 - tau/L) fades to zero over the blend.
        const auto travel = static_cast<float>(tau - tau * tau / (2 * length));
        const auto fade = static_cast<float>(1 - tau / length);
        for (std::size_t i = 0; i < src_e.size(); ++i) {
            src_e[i] = inertial_euler_[i] + inertial_vel_euler_[i] * travel;
            src_p[i] = inertial_position_[i] + inertial_vel_position_[i] * travel;
            if (want_velocity) {
                src_ve[i] = inertial_vel_euler_[i] * fade;
                src_vp[i] = inertial_vel_position_[i] * fade;
            }
        }
    }
    // Smoothstep weight: w(0) = 0 with w'(0) = 0, so at the switch the output equals the source in value
    // and velocity; w(1) = 1 with w'(1) = 0, so it settles onto the clip without a kink.
    const double u = tau / length;
    const auto w = static_cast<float>(u * u * (3 - 2 * u));
    const auto dw = static_cast<float>(6 * u * (1 - u) / length);
    for (std::size_t i = 0; i < euler.size(); ++i) {
        const Vec3 de = euler[i] - src_e[i], dp = position[i] - src_p[i];
        if (want_velocity) {
            vel_euler[i] = src_ve[i] + (vel_euler[i] - src_ve[i]) * w + de * dw;
            vel_position[i] = src_vp[i] + (vel_position[i] - src_vp[i]) * w + dp * dw;
        }
        euler[i] = src_e[i] + de * w;
        position[i] = src_p[i] + dp * w;
    }
}

void Player::refresh_pose() {
    evaluate(pose_.euler, pose_.position, {}, {});
    pose_.update_rotations();
}

void Player::velocity(std::span<Vec3> euler_rate, std::span<Vec3> position_rate) {
    evaluate(a_euler_, a_position_, euler_rate, position_rate);
}

void Player::play(int clip) {
    play(clip, clips_.blend_time(current_.clip, clip));
}

void Player::play(int clip, float blend_seconds) {
    if (clip < 0 || clip >= static_cast<int>(clips_.clips.size())) return;
    const bool blend = blend_seconds > 0 && std::isfinite(blend_seconds);
    // Capture the output (and its velocity when blending) at this instant.
    evaluate(a_euler_, a_position_, blend ? std::span<Vec3>(a_vel_euler_) : std::span<Vec3>(),
             blend ? std::span<Vec3>(a_vel_position_) : std::span<Vec3>());
    const bool wrap = clips_.wrap_captured_angles;
    for (std::size_t i = 0; i < a_euler_.size(); ++i) {
        const Vec3 e = wrap ? wrap_angles(a_euler_[i]) : a_euler_[i];
        current_.start_euler[i] = e;
        current_.start_position[i] = a_position_[i];
        if (blend) {
            inertial_euler_[i] = e;
            inertial_position_[i] = a_position_[i];
            inertial_vel_euler_[i] = a_vel_euler_[i];
            inertial_vel_position_[i] = a_vel_position_[i];
        }
    }
    current_.clip = clip;
    current_.start = now_;
    events_done_ = -1;
    source_ = blend ? Source::Inertial : Source::None;
    blend_start_ = now_;
    blend_length_ = blend ? std::max<std::int64_t>(1, to_flicks(blend_seconds)) : 0;
    refresh_pose();
}

void Player::crossfade(int clip, float seconds) {
    if (clip < 0 || clip >= static_cast<int>(clips_.clips.size())) return;
    if (blending() || !(seconds > 0) || !std::isfinite(seconds)) { // a blend of blends: capture instead
        play(clip, seconds);
        return;
    }
    // The old clip keeps running as the source. The new one starts from the current pose, unwrapped, so that
    // both sides of the blend use the same Euler branch.
    evaluate(a_euler_, a_position_, {}, {});
    std::swap(fading_, current_);
    for (std::size_t i = 0; i < a_euler_.size(); ++i) {
        current_.start_euler[i] = a_euler_[i];
        current_.start_position[i] = a_position_[i];
    }
    current_.clip = clip;
    current_.start = now_;
    events_done_ = -1;
    source_ = Source::Crossfade;
    blend_start_ = now_;
    blend_length_ = std::max<std::int64_t>(1, to_flicks(seconds));
    refresh_pose();
}

// Reports the current clip's events in (events_done_, until - start] of its own time.
void Player::collect_events(std::int64_t until) {
    if (current_.clip < 0) return;
    const Clip& clip = clips_.clips[static_cast<std::size_t>(current_.clip)];
    const std::int64_t from = events_done_, to = until - current_.start;
    events_done_ = std::max(events_done_, to);
    if (clip.events.empty() || to <= from) return;
    const std::int64_t length = to_flicks(clip.duration);
    const bool ping_pong = clip.loop == LoopMode::PingPong && length > 0;
    const bool loops = (clip.loop == LoopMode::Loop || ping_pong) && length > 0;
    const std::int64_t period = ping_pong ? 2 * length : length;
    auto fire = [&](std::int64_t at, const ClipEvent& e) {
        if (at > from && at <= to && fired_.size() < fired_.capacity()) fired_.push_back({current_.clip, &e});
    };
    // A looping clip reports each iteration it crossed, at most a few per advance (a huge step of a tiny loop
    // would otherwise flood the list).
    constexpr std::int64_t kMaxIterations = 4;
    const std::int64_t first = loops ? std::max<std::int64_t>(0, from) / period : 0;
    const std::int64_t last = loops ? std::min(to / period, first + kMaxIterations - 1) : 0;
    for (std::int64_t k = first; k <= last; ++k) {
        for (const ClipEvent& e : clip.events) fire(k * period + to_flicks(e.time), e);
        if (!ping_pong) continue;
        // The way back passes the events again, latest first; one at either turn (0 or the end) is the same
        // instant as its forward firing, so it fires once.
        for (auto it = clip.events.rbegin(); it != clip.events.rend(); ++it) {
            const std::int64_t at = to_flicks(it->time);
            if (at > 0 && at < length) fire(k * period + period - at, *it);
        }
    }
}

void Player::advance(double dt_seconds) {
    fired_.clear();
    if (!(dt_seconds > 0)) return;
    const std::int64_t target = now_ + to_flicks(dt_seconds);
    // Hand over to the next clip at the exact end of a Next clip (bounded in case of a chain of empty clips).
    for (int guard = 0; guard < 64 && current_.clip >= 0; ++guard) {
        const Clip& clip = clips_.clips[static_cast<std::size_t>(current_.clip)];
        if (clip.loop != LoopMode::Next || clip.next < 0) break;
        const std::int64_t end = current_.start + to_flicks(clip.duration);
        if (end > target) break;
        now_ = end;
        collect_events(end);
        play(clip.next);
    }
    now_ = target;
    collect_events(target);
    refresh_pose();
}

bool Player::finished() const {
    if (current_.clip < 0) return true;
    const Clip& clip = clips_.clips[static_cast<std::size_t>(current_.clip)];
    return clip.loop == LoopMode::Once && clip_time() >= clip.duration && !blending();
}

} // namespace ks::anim
