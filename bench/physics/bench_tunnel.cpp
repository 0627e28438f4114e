// ks_bench tunnel: how often a character (capsule radius 0.25, like a thrown or knocked-back body; and the
// radius-1 player) ends up on the far side of a 5 cm wall, against speed and frame rate, for three ways of
// moving: discrete (move, then push out along the contact normal: the reference's way, plus a real push),
// sub-stepped (the same in steps of at most half the radius) and swept (our character controller).
#include "bench_registry.h"
#include "bench_util.h"
#include "physics/character.h"

#include "core/random.h"

#include <cmath>
#include <cstdio>

namespace ks::physics::bench {
namespace {

constexpr float kWallX = 10.0f, kWallHalf = 0.025f;

class OneWall final : public ObstacleSource {
  public:
    explicit OneWall(const Shape& wall) : wall_(wall) {}
    void gather(const geometry::Aabb&, std::vector<Obstacle>& out) const override {
        out.push_back({&wall_, {{kWallX, 0, 0}, Quat(1, 0, 0, 0)}, 1, true});
    }

  private:
    const Shape& wall_;
};

enum class Method { Discrete, SubStepped, Swept };

// One trial: start left of the wall, move right at `speed` for 1 s of frames at `fps`; true when it ends
// beyond the wall.
bool trial(Method m, float radius, float speed, float fps, float phase, const Shape& wall,
           CharacterScratch& scratch) {
    const float dt = 1.0f / fps;
    Vec3 p(kWallX - radius - 0.1f - phase * speed * dt, 0, 0);
    const Vec3 v(speed, 0, 0);
    auto push_out = [&](Vec3& q) {
        const Segment s{q - Vec3(0, 0.5f, 0), q + Vec3(0, 0.5f, 0)};
        if (auto c = collide_capsule_box(s, radius, wall.half_extents, {{kWallX, 0, 0}, Quat(1, 0, 0, 0)}))
            if (c->penetration > 0) q += c->normal * c->penetration;
    };
    if (m == Method::Swept) {
        OneWall source(wall);
        CharacterState st;
        st.movement.gravity = 0;
        st.movement.max_speed = 1e5f;
        for (float t = 0; t < 1.0f; t += dt) {
            st.movement.velocity = v;
            move_character(source, radius, 0.5f, {}, st, p, dt, scratch);
        }
    } else {
        const int sub = m == Method::SubStepped
                            ? std::max(1, static_cast<int>(std::ceil(speed * dt / (0.5f * radius))))
                            : 1;
        for (float t = 0; t < 1.0f; t += dt)
            for (int k = 0; k < sub; ++k) {
                p += v * (dt / sub);
                push_out(p);
            }
    }
    return p.x > kWallX;
}

int tunnel_command(int, const char* const*) {
    const Shape wall = Shape::box({kWallHalf, 5, 20});
    CharacterScratch scratch;
    Rng rng(8);
    const float speeds[] = {5, 15, 25, 50, 100, 200, 400};
    const float rates[] = {15, 30, 60, 120, 240};
    std::vector<std::string> rows;
    double plot_rates[3][7] = {};
    std::printf(
        "Tunnelling through a 5 cm wall: %% of 50 trials (random start phase) ending on the far side.\n");
    for (float radius : {0.25f, 1.0f}) {
        std::printf("\ncapsule radius %.2f\n%-12s %6s", radius, "method", "fps");
        for (float s : speeds) std::printf(" %7.0f", s);
        std::printf("   (speed, u/s)   CPU us/step at 50 u/s\n");
        for (auto [name, m] :
             {std::pair{"discrete", Method::Discrete}, std::pair{"sub-stepped", Method::SubStepped},
              std::pair{"swept", Method::Swept}}) {
            for (float fps : rates) {
                std::printf("%-12s %6.0f", name, fps);
                std::string row = std::string(name) + "," + fmt("%.2f", radius) + "," + fmt("%.0f", fps);
                for (int si = 0; si < 7; ++si) {
                    int through = 0;
                    for (int t = 0; t < 50; ++t)
                        through += trial(m, radius, speeds[si], fps, rng.uniform(), wall, scratch);
                    std::printf(" %6.0f%%", through * 2.0);
                    row += "," + fmt("%.0f", through * 2.0);
                    if (radius == 0.25f && fps == 60.0f) plot_rates[static_cast<int>(m)][si] = through * 2.0;
                }
                const double t0 = cpu_seconds();
                for (int t = 0; t < 20; ++t) trial(m, radius, 50, fps, 0.5f, wall, scratch);
                const double us = (cpu_seconds() - t0) / (20.0 * fps) * 1e6;
                std::printf("   %8.3f\n", us);
                rows.push_back(row + "," + fmt("%.4f", us));
            }
        }
    }
    std::string header = "method,radius,fps";
    for (float s : speeds) header += ",v" + fmt("%.0f", s);
    header += ",cpu_us_per_step_at_50";
    write_csv("physics_tunnel", header, rows);
    std::vector<std::string> plot_rows;
    for (int si = 0; si < 7; ++si)
        plot_rows.push_back(fmt("%.0f", speeds[si]) + "," + fmt("%.0f", plot_rates[0][si]) + "," +
                            fmt("%.0f", plot_rates[1][si]) + "," + fmt("%.0f", plot_rates[2][si]));
    write_csv("physics_tunnel_plot", "speed,discrete,sub_stepped,swept", plot_rows);
    plot("physics_tunnel",
         "set title 'Tunnelling through a 5 cm wall at 60 fps (capsule radius 0.25)'\n"
         "set xlabel 'speed (u/s)'\nset ylabel '% of trials through the wall'\nset logscale x\n"
         "set yrange [-5:105]\nset key center left\n"
         "plot 'physics_tunnel_plot.csv' every ::1 using 1:2 with linespoints title 'discrete', \\\n"
         "     '' every ::1 using 1:3 with linespoints title 'sub-stepped (r/2)', \\\n"
         "     '' every ::1 using 1:4 with linespoints title 'swept (ours)'\n");
    return 0;
}

const ks::bench::Registrar registrar({"tunnel",
                                      "tunnelling rate vs speed and frame rate: discrete, sub-stepped, swept",
                                      tunnel_command});

} // namespace
} // namespace ks::physics::bench
