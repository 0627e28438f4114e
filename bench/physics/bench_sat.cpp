// ks_bench sat: (1) face-only SAT (the reference's way) vs full SAT with edge×edge axes on random box pairs:
// false-contact rate and penetration error against a double-precision SAT, and ns per test; (2) the
// reference's polygonised character cylinder (N = 8..64 sides, hull + SAT) vs our analytic capsule and
// analytic cylinder against walls: penetration error vs ns per test.
#include "bench_registry.h"
#include "bench_util.h"
#include "physics/collide.h"

#include "core/random.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace ks::physics::bench {
namespace {

using DQuat = glm::dquat;

// Full SAT in double over the same axes (all face normals, all edge pairs): the reference for (1).
// Returns the penetration, or -1 when separated.
double sat_double(const Vec3& ha, const DQuat& qa, const DVec3& pa, const Vec3& hb, const DQuat& qb,
                  const DVec3& pb) {
    DVec3 va[8], vb[8];
    for (int i = 0; i < 8; ++i) {
        const DVec3 s(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
        va[i] = pa + qa * (DVec3(ha) * s);
        vb[i] = pb + qb * (DVec3(hb) * s);
    }
    DVec3 axes[15];
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        DVec3 e(0.0);
        e[i] = 1.0;
        axes[n++] = qa * e;
        axes[n++] = qb * e;
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            DVec3 ei(0.0), ej(0.0);
            ei[i] = 1.0;
            ej[j] = 1.0;
            const DVec3 c = glm::cross(qa * ei, qb * ej);
            if (glm::length(c) > 1e-9) axes[n++] = glm::normalize(c);
        }
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < n; ++k) {
        double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
        for (int i = 0; i < 8; ++i) {
            a0 = std::min(a0, glm::dot(va[i], axes[k])), a1 = std::max(a1, glm::dot(va[i], axes[k]));
            b0 = std::min(b0, glm::dot(vb[i], axes[k])), b1 = std::max(b1, glm::dot(vb[i], axes[k]));
        }
        if (a0 > b1 || b0 > a1) return -1.0;
        best = std::min(best, std::min(b1 - a0, a1 - b0));
    }
    return best;
}

Quat random_rotation(Rng& rng) {
    return glm::normalize(
        Quat(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
}

void box_pairs(bool quick) {
    const int pairs = quick ? 20000 : 200000;
    Rng rng(3);
    struct Pair {
        Vec3 ha, hb;
        geometry::Transform a, b;
        double truth;
    };
    std::vector<Pair> set;
    set.reserve(pairs);
    while (static_cast<int>(set.size()) < pairs) {
        Pair p;
        p.ha = {rng.uniform(0.2f, 2), rng.uniform(0.2f, 2), rng.uniform(0.2f, 2)};
        p.hb = {rng.uniform(0.2f, 2), rng.uniform(0.2f, 2), rng.uniform(0.2f, 2)};
        p.a = {{0, 0, 0}, random_rotation(rng)};
        // Near contact: offsets of about the sum of the sizes, so many pairs are close calls.
        const float reach = glm::length(p.ha) + glm::length(p.hb);
        p.b = {Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * reach * 0.8f,
               random_rotation(rng)};
        p.truth = sat_double(p.ha, glm::dquat(p.a.rotation), DVec3(p.a.position), p.hb,
                             glm::dquat(p.b.rotation), DVec3(p.b.position));
        set.push_back(p);
    }
    std::vector<Polyhedron> pa, pb;
    for (const auto& p : set)
        pa.push_back(make_box_polyhedron(p.ha)), pb.push_back(make_box_polyhedron(p.hb));
    std::printf("Box pairs near contact, %d random orientations; truth: full SAT in double.\n", pairs);
    std::printf("%-22s %10s %14s %14s %16s %10s\n", "method", "ns/test", "false contact", "missed",
                "max |pen err|", "contacts");
    std::vector<std::string> rows;
    for (auto [name, axes] : {std::pair{"face-only SAT (ref.)", SatAxes::FacesOnly},
                              std::pair{"full SAT (faces+edges)", SatAxes::FacesAndEdges}}) {
        long long false_contact = 0, missed = 0, contacts = 0;
        double max_err = 0;
        const double t0 = cpu_seconds();
        for (std::size_t i = 0; i < set.size(); ++i) {
            const auto c = collide_convex(pa[i], set[i].a, pb[i], set[i].b, axes);
            contacts += c.has_value();
            const bool truth = set[i].truth >= 0.0;
            if (c && !truth) ++false_contact;
            if (!c && truth) ++missed;
            if (c && truth) max_err = std::max(max_err, std::abs(c->penetration - set[i].truth));
        }
        const double ns = (cpu_seconds() - t0) * 1e9 / set.size();
        std::printf("%-22s %10.1f %13.2f%% %14lld %16.3g %10lld\n", name, ns,
                    100.0 * false_contact / set.size(), missed, max_err, contacts);
        rows.push_back(std::string(name) + "," + fmt("%.1f", ns) + "," +
                       fmt("%.4f", 100.0 * false_contact / set.size()) + "," + std::to_string(missed) + "," +
                       fmt("%.3g", max_err));
    }
    write_csv("physics_sat_boxes",
              "method,ns_per_test,false_contact_percent,missed,max_abs_penetration_error", rows);
}

// Exact upright cylinder (radius r, half height h) against a yaw-only box, in double: a disc against a
// rectangle in the box's plan, and intervals along y. Penetration (minimum push), or -1 when apart.
double cylinder_box_exact(const DVec3& c, double r, double h, const DVec3& box_centre, double yaw,
                          const DVec3& half) {
    const DVec3 l = glm::conjugate(glm::angleAxis(yaw, DVec3(0, 1, 0))) * (c - box_centre);
    const double pen_v = std::min(l.y + h + half.y, half.y - (l.y - h));
    const double dx = std::max(std::abs(l.x) - half.x, 0.0), dz = std::max(std::abs(l.z) - half.z, 0.0);
    double pen_h;
    if (dx > 0 || dz > 0)
        pen_h = r - std::sqrt(dx * dx + dz * dz);
    else
        pen_h = r + std::min(half.x - std::abs(l.x), half.z - std::abs(l.z));
    if (pen_v < 0 || pen_h < 0) return -1.0;
    return std::min(pen_v, pen_h);
}

Polyhedron prism(int sides, float r, float h) {
    std::vector<Vec3> pts;
    for (int i = 0; i < sides; ++i) {
        const float a = 2.0f * kPi * i / sides;
        pts.push_back({r * std::cos(a), -h, r * std::sin(a)});
        pts.push_back({r * std::cos(a), h, r * std::sin(a)});
    }
    return *build_convex_hull(pts, "prism");
}

void characters(bool quick) {
    const int tests = quick ? 20000 : 200000;
    Rng rng(4);
    struct Case {
        Vec3 centre;
        Vec3 half;
        float yaw;
        Vec3 box_centre;
    };
    std::vector<Case> set;
    for (int i = 0; i < tests; ++i) {
        Case c;
        c.half = {rng.uniform(0.2f, 6), rng.uniform(0.2f, 8), rng.uniform(0.1f, 6)};
        c.yaw = rng.uniform(0, kPi);
        c.box_centre = {0, 0, 0};
        const Vec3 dir =
            glm::normalize(Vec3(rng.uniform(-1, 1), rng.uniform(-0.3f, 0.3f), rng.uniform(-1, 1)));
        c.centre = dir * (glm::length(c.half) * rng.uniform(0.3f, 1.2f));
        set.push_back(c);
    }
    std::printf(
        "\nCharacter (radius 1, height 3) against walls/crates near contact: penetration error vs the exact\n"
        "shape the method stands for (the polygonised prism approximates the reference's cylinder).\n");
    std::printf("%-28s %10s %16s %16s %12s\n", "method", "ns/test", "mean |pen err|", "max |pen err|",
                "wrong y/n");
    std::vector<std::string> rows;
    auto report = [&](const std::string& name, double ns, double sum, double max, long long wrong,
                      int sides) {
        std::printf("%-28s %10.1f %16.4g %16.4g %12lld\n", name.c_str(), ns, sum / tests, max, wrong);
        rows.push_back(name + "," + std::to_string(sides) + "," + fmt("%.1f", ns) + "," +
                       fmt("%.5g", sum / tests) + "," + fmt("%.5g", max) + "," + std::to_string(wrong));
    };
    for (int sides : {8, 16, 32, 64}) {
        const Polyhedron cyl = prism(sides, 1.0f, 1.5f);
        for (auto axes : {SatAxes::FacesOnly, SatAxes::FacesAndEdges}) {
            double sum = 0, max = 0;
            long long wrong = 0;
            std::vector<Polyhedron> boxes;
            for (const auto& c : set) boxes.push_back(make_box_polyhedron(c.half));
            const double t0 = cpu_seconds();
            std::vector<float> pens(set.size());
            for (std::size_t i = 0; i < set.size(); ++i) {
                const auto r =
                    collide_convex(cyl, {set[i].centre, Quat(1, 0, 0, 0)}, boxes[i],
                                   {set[i].box_centre, glm::angleAxis(set[i].yaw, Vec3(0, 1, 0))}, axes);
                pens[i] = r ? r->penetration : -1.0f;
            }
            const double ns = (cpu_seconds() - t0) * 1e9 / set.size();
            for (std::size_t i = 0; i < set.size(); ++i) {
                const double truth = cylinder_box_exact(
                    DVec3(set[i].centre), 1.0, 1.5, DVec3(set[i].box_centre), set[i].yaw, DVec3(set[i].half));
                if ((pens[i] >= 0) != (truth >= 0))
                    ++wrong;
                else if (truth >= 0) {
                    sum += std::abs(pens[i] - truth);
                    max = std::max(max, std::abs(pens[i] - truth));
                }
            }
            report("prism " + std::to_string(sides) +
                       (axes == SatAxes::FacesOnly ? " face-only SAT" : " full SAT"),
                   ns, sum, max, wrong, sides);
        }
    }
    // Analytic capsule (our characters) against the same boxes: exact closest features, checked against the
    // same computation in double.
    {
        std::vector<float> pens(set.size());
        const double t0 = cpu_seconds();
        for (std::size_t i = 0; i < set.size(); ++i) {
            const Segment s{set[i].centre - Vec3(0, 0.5f, 0), set[i].centre + Vec3(0, 0.5f, 0)};
            const auto r = collide_capsule_box(
                s, 1.0f, set[i].half, {set[i].box_centre, glm::angleAxis(set[i].yaw, Vec3(0, 1, 0))});
            pens[i] = r ? r->penetration : -1e9f;
        }
        const double ns = (cpu_seconds() - t0) * 1e9 / set.size();
        double sum = 0, max = 0;
        long long wrong = 0;
        for (std::size_t i = 0; i < set.size(); ++i) {
            // Double: distance from the vertical core segment to the box (in the box frame), minus the
            // radius.
            const DVec3 l = glm::conjugate(glm::angleAxis(double(set[i].yaw), DVec3(0, 1, 0))) *
                            (DVec3(set[i].centre) - DVec3(set[i].box_centre));
            const DVec3 h(set[i].half);
            const double dx = std::max(std::abs(l.x) - h.x, 0.0), dz = std::max(std::abs(l.z) - h.z, 0.0);
            const double dy = std::max({(l.y - 0.5) - h.y, -h.y - (l.y + 0.5), 0.0});
            const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
            double truth;
            if (dist > 0)
                truth = 1.0 - dist;
            else
                truth = 1.0 + std::min({h.x - std::abs(l.x), h.z - std::abs(l.z), h.y - (l.y - 0.5),
                                        (l.y + 0.5) + h.y});
            const bool hit = pens[i] > -1e8f && pens[i] >= 0.0f, want = truth >= 0;
            if (hit != want && std::abs(truth) > 1e-5)
                ++wrong;
            else if (want && hit) {
                sum += std::abs(pens[i] - truth);
                max = std::max(max, std::abs(pens[i] - truth));
            }
        }
        report("analytic capsule (ours)", ns, sum, max, wrong, 0);
    }
    write_csv("physics_sat_characters",
              "method,sides,ns_per_test,mean_abs_penetration_error,max_abs_penetration_error,"
              "wrong_contact_verdicts",
              rows);
    plot("physics_sat_characters",
         "set title 'Character vs box: penetration error vs cost'\nset logscale xy\nset format y '%.0e'\nset "
         "xlabel 'ns per test'\n"
         "set ylabel 'mean |penetration error| (units)'\nset key top right\n"
         "plot 'physics_sat_characters.csv' every ::1 using ($2>0 && strstrt(strcol(1),'face-only')>0 ? $3 : "
         "1/0):4:2 "
         "with labels point pt 7 offset 1,0.5 title 'polygonised cylinder, face-only SAT (label = sides)', "
         "\\\n"
         "     '' every ::1 using ($2>0 && strstrt(strcol(1),'full')>0 ? $3 : 1/0):4 with points pt 5 ps 1.5 "
         "title 'polygonised cylinder, full SAT', \\\n"
         "     '' every ::1 using ($2==0 ? $3 : 1/0):($4 > 1e-9 ? $4 : 1e-9) with points pt 9 ps 2.5 "
         "title 'analytic capsule (ours; error at float rounding)'\n");
}

int sat_command(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i) quick |= std::string(argv[i]) == "--quick";
    box_pairs(quick);
    characters(quick);
    return 0;
}

const ks::bench::Registrar
    registrar({"sat", "face-only vs full SAT; polygonised cylinder vs analytic capsule", sat_command});

} // namespace
} // namespace ks::physics::bench
