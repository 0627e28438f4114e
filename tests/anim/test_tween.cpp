#include "anim/tween.h"

#include <doctest/doctest.h>
#include <string>

using namespace ks;
using namespace ks::anim;

namespace {
TweenTiming timing(double duration, double delay = 0, int repeat = 0, bool yoyo = false) {
    TweenTiming t;
    t.duration = duration;
    t.delay = delay;
    t.repeat = repeat;
    t.yoyo = yoyo;
    return t;
}
} // namespace

TEST_CASE("a float tween is a pure function of time: delay, easing, hold at the end") {
    TweenTiming t = timing(2.0, 0.5);
    t.ease = Ease::named(EaseFamily::Quadratic, EaseMode::In);
    Tween<float> tw(10.0f, 20.0f, t);
    CHECK(tw.value_at(-1.0) == 10.0f);
    CHECK(tw.value_at(0.4) == 10.0f);
    CHECK(tw.value_at(1.5) == doctest::Approx(12.5f)); // progress 0.5 -> 0.25
    CHECK(tw.value_at(2.5) == 20.0f);
    CHECK(tw.value_at(100.0) == 20.0f);
    CHECK(t.total() == doctest::Approx(2.5));
}

TEST_CASE("repeat and yoyo, finite and endless") {
    Tween<float> tw(0.0f, 1.0f, timing(1.0, 0, 2, true)); // 3 iterations: up, down, up
    CHECK(tw.value_at(0.25) == doctest::Approx(0.25f));
    CHECK(tw.value_at(1.25) == doctest::Approx(0.75f)); // reversed
    CHECK(tw.value_at(2.25) == doctest::Approx(0.25f));
    CHECK(tw.value_at(3.5) == 1.0f); // ends after an odd number of iterations: at `to`
    Tween<float> even(0.0f, 1.0f, timing(1.0, 0, 1, true));
    CHECK(even.value_at(5.0) == 0.0f); // up then down
    TweenTiming forever = timing(0.5, 0, kRepeatForever);
    Tween<float> loop(0.0f, 1.0f, forever);
    CHECK(loop.value_at(1000.25) == doctest::Approx(0.5f));
    CHECK(std::isinf(forever.total()));
    // A repeat delay holds the end value between iterations.
    TweenTiming gap = timing(1.0, 0, 1);
    gap.repeat_delay = 0.5;
    Tween<float> gapped(0.0f, 1.0f, gap);
    CHECK(gapped.value_at(1.25) == 1.0f);
    CHECK(gapped.value_at(1.75) == doctest::Approx(0.25f));
    CHECK(gap.total() == doctest::Approx(2.5));
}

TEST_CASE("vec3 and quaternion tweens; quaternions take the short way") {
    Tween<Vec3> v(Vec3(0), Vec3(2, 4, 6), timing(1.0));
    CHECK(v.value_at(0.5).y == doctest::Approx(2.0f));
    const Quat a = glm::angleAxis(0.1f, Vec3(0, 1, 0));
    const Quat b = -glm::angleAxis(0.5f, Vec3(0, 1, 0)); // same rotation, opposite sign
    Tween<Quat> q(a, b, timing(1.0));
    const Quat mid = q.value_at(0.5);
    CHECK(angle_between(mid, glm::angleAxis(0.3f, Vec3(0, 1, 0))) < 1e-6f);
    CHECK(glm::length(mid) == doctest::Approx(1.0f).epsilon(1e-6));
}

TEST_CASE("callbacks fire once each, whatever the step size") {
    for (double step : {0.01, 0.3, 10.0}) {
        TweenGroup group;
        float target = -1;
        int starts = 0, updates = 0, repeats = 0, completes = 0;
        auto& tw = group.add(Tween<float>(0, 1, timing(1.0, 0.5, 2), &target));
        tw.on_start = [&] { ++starts; };
        tw.on_update = [&](const float&, double) { ++updates; };
        tw.on_repeat = [&](long long) { ++repeats; };
        tw.on_complete = [&] { ++completes; };
        for (int i = 0; i < 1000 && !group.idle(); ++i) group.update(step);
        INFO("step ", step);
        CHECK(starts == 1);
        CHECK(repeats == 2);
        CHECK(completes == 1);
        CHECK(updates >= 1);
        CHECK(target == 1.0f);
        CHECK(group.idle());
    }
}

TEST_CASE("chain starts the next tween exactly when the first completes; time scale stretches it") {
    TweenGroup group;
    float x = 0, y = 0;
    auto& first = group.add(Tween<float>(0, 1, timing(1.0), &x));
    TweenTiming slow = timing(1.0);
    slow.time_scale = 0.5; // takes 2 s of group time
    auto& second = group.add(Tween<float>(0, 10, slow, &y));
    first.chain(second);
    double second_started_at = -1;
    second.on_start = [&] { second_started_at = group.time(); };
    CHECK(group.start_time(second) == doctest::Approx(1.0));
    CHECK(group.end_time(second) == doctest::Approx(3.0));
    group.seek(0.5);
    CHECK(y == 0.0f);
    CHECK(second_started_at < 0);
    group.seek(2.0);
    CHECK(second_started_at == doctest::Approx(2.0));
    CHECK(y == doctest::Approx(5.0f));
    group.seek(3.5);
    CHECK(y == 10.0f);
    CHECK(group.idle());
}

TEST_CASE("seeking backwards re-arms callbacks without firing them; scrubbing gives the pure values") {
    TweenGroup group;
    float x = 0;
    int starts = 0, completes = 0;
    auto& tw = group.add(Tween<float>(0, 1, timing(1.0), &x));
    tw.on_start = [&] { ++starts; };
    tw.on_complete = [&] { ++completes; };
    group.seek(2.0);
    CHECK(completes == 1);
    group.seek(0.25);
    CHECK(x == doctest::Approx(0.25f));
    CHECK_FALSE(tw.completed());
    CHECK(starts == 1);
    CHECK(completes == 1);
    group.seek(1.5);
    CHECK(completes == 2); // played through again
    for (double t : {0.9, 0.1, 0.6, 0.3}) {
        group.seek(t);
        CHECK(x == doctest::Approx(tw.value_at(t)));
    }
}

TEST_CASE("stop freezes the value, fires on_stop and stops chained tweens") {
    TweenGroup group;
    float x = 0, y = 0;
    int stops = 0;
    auto& a = group.add(Tween<float>(0, 1, timing(1.0), &x));
    auto& b = group.add(Tween<float>(0, 1, timing(1.0), &y));
    a.chain(b);
    a.on_stop = [&] { ++stops; };
    group.seek(0.5);
    group.stop(a);
    group.stop(a); // second stop: no second callback
    group.seek(3.0);
    CHECK(stops == 1);
    CHECK(x == doctest::Approx(0.5f));
    CHECK(y == 0.0f);
    CHECK(b.stopped());
    CHECK(group.idle());
}

TEST_CASE("group time scale and an endless tween keeping the group busy") {
    TweenGroup group;
    float x = 0;
    group.add(Tween<float>(0, 1, timing(1.0, 0, kRepeatForever), &x));
    group.set_time_scale(2.0);
    group.update(0.125);
    CHECK(group.time() == doctest::Approx(0.25));
    CHECK(x == doctest::Approx(0.25f));
    group.update(1e6);
    CHECK_FALSE(group.idle());
}

TEST_CASE("hard cases: zero duration, NaN and huge times, huge repeat counts") {
    Tween<float> instant(0.0f, 1.0f, timing(0.0, 0.25));
    CHECK(instant.value_at(0.2) == 0.0f);
    CHECK(instant.value_at(0.25) == 1.0f);
    CHECK(instant.value_at(std::nan("")) == 0.0f);
    Tween<float> tw(0.0f, 1.0f, timing(0.1, 0, 1000001, true)); // last iteration (1000001) runs backwards
    CHECK(tw.value_at(1e12) == 0.0f);
    CHECK(tw.value_at(0.1 * 1000001 + 0.05) == doctest::Approx(0.5f).epsilon(1e-3)); // last one, reversed
    TweenTiming forever = timing(0.1, 0, kRepeatForever, true);
    Tween<float> endless(0.0f, 1.0f, forever);
    for (double t : {1e3, 1e9, 1e15}) {
        const float v = endless.value_at(t + 0.05);
        CHECK(std::isfinite(v));
        CHECK(v >= 0.0f);
        CHECK(v <= 1.0f);
    }
    CHECK(std::isfinite(endless.value_at(std::numeric_limits<double>::max())));
    TweenGroup group; // zero-length iterations complete at once and fire every callback once
    int completes = 0, repeats = 0;
    auto& zero = group.add(Tween<float>(0, 1, timing(0.0, 0, 3)));
    zero.on_complete = [&] { ++completes; };
    zero.on_repeat = [&](long long) { ++repeats; };
    group.update(0.0);
    CHECK(completes == 1);
    CHECK(repeats == 3);
}
