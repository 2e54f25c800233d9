// `ricochet bench meet` (meet_bench.hpp): the scenes, the counting run and the timed repetitions, the table.
#include "meet_bench.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine.hpp"

namespace ricochet::meet_bench {

// An engine not found at build time makes no rows.
#ifndef RICOCHET_HAVE_BOX2D
std::unique_ptr<Engine> make_box2d(const MeetScene&, bool) { return nullptr; }
#endif
#ifndef RICOCHET_HAVE_CHIPMUNK
std::unique_ptr<Engine> make_chipmunk(const MeetScene&, bool) { return nullptr; }
#endif

namespace {

/// The calling thread's CPU time in seconds: on a shared machine, time spent descheduled is not the engine's cost.
double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct SceneSpec {
    const char* name;
    int n;
    double v_max;
    std::int64_t frames;
    bool count;  // count what the engines missed (the cost scene is only timed)
};

struct EngineSpec {
    const char* name;
    std::unique_ptr<Engine> (*make)(const MeetScene&, bool record);
};

const EngineSpec k_engines[] = {
    {"ricochet robust", [](const MeetScene& s, bool) { return make_ricochet(s, KernelId::robust); }},
    {"ricochet lecture-double", [](const MeetScene& s, bool) { return make_ricochet(s, KernelId::lecture_double); }},
    {"Box2D 2.4.1 (bullets)", make_box2d},
    {"Chipmunk 7", make_chipmunk},
};
constexpr std::size_t k_engine_count = std::size(k_engines);

/// The disc radius of every scene.
constexpr double k_radius = 0.5;

}  // namespace

int run_meet_bench(MeetSize size, std::uint64_t seed, std::int64_t frames) {
    const bool smoke = size == MeetSize::smoke, quick = size == MeetSize::quick;
    const int reps = smoke ? 1 : quick ? 3 : 5;
    // Each run stops when it has spent this much CPU time: Box2D's bullets on the fast scene take tens of seconds a
    // frame (docs/bench-meet.md); its row then covers the frames it got through.
    const double budget = smoke ? INFINITY : quick ? 20.0 : 120.0;
    if (frames <= 0) frames = smoke ? 5 : quick ? 50 : 200;
    std::vector<SceneSpec> scenes{{"a: slow", smoke ? 25 : 1000, 2.0, frames, true},
                                  {"b: fast", smoke ? 25 : 1000, 20.0, frames, true}};
    if (!smoke) scenes.push_back({"c: cost", 10000, 2.0, std::max<std::int64_t>(1, frames / 4), false});

    // The table is printed whole at the end: Chipmunk prints a line of its own when its first space is made.
    std::string table = fmt::format(
        "ricochet bench meet{}: seed {}; discs R = {} in a closed box ({} of its area), masses 1, restitution 1, "
        "dt = 1 a frame\n",
        smoke ? " --smoke" : quick ? " --quick" : "", seed, k_radius, k_area_fraction);
    table += fmt::format("ns/ball-frame: this thread's CPU time stepping (set-up left out), median of {} run{}; counts "
                         "from one more run, exact on every frame's end state{}\n\n",
                         reps, reps == 1 ? "" : "s",
                         std::isinf(budget) ? "" : fmt::format("; a run stops after {} s CPU", budget));
    table += "| scene | engine | frames | ns/ball-frame | overlaps | pass-throughs | deepest | unsure | escaped | "
             "energy drift (end, max) | notes |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | --- "
             "|\n";
    int rc = 0;
    for (const SceneSpec& spec : scenes) {
        const MeetScene scene = make_scene(spec.n, k_radius, spec.v_max, spec.frames, seed);
        const std::string label =
            fmt::format("{}: {} discs, speeds ≤ {}, box {}", spec.name, spec.n, spec.v_max, scene.side);
        const double ball_count = static_cast<double>(spec.n);
        // The counting run: the engines' contacts recorded, every frame counted.
        Counts counts[k_engine_count];
        std::string notes[k_engine_count];
        bool built[k_engine_count] = {};
        std::int64_t stepped[k_engine_count] = {};
        std::vector<double> ns[k_engine_count];
        for (std::size_t e = 0; e < k_engine_count; ++e) {
            const std::unique_ptr<Engine> engine = k_engines[e].make(scene, spec.count);
            if (!engine) continue;
            built[e] = true;
            if (!spec.count) continue;
            MeetCounter counter(engine->side(), engine->balls());
            const double t0 = cpu_now();
            double spent = 0.0;
            while (stepped[e] < spec.frames && spent < budget) {
                const double s0 = cpu_now();
                engine->step();
                spent += cpu_now() - s0;
                counter.add(engine->frame());
                ++stepped[e];
            }
            counts[e] = counter.counts();
            notes[e] = engine->notes();
            // Cut short: this run's stepping time is the only one (the counter's time left out).
            if (stepped[e] < spec.frames) ns[e].push_back(spent * 1e9 / (ball_count * static_cast<double>(stepped[e])));
            fmt::print(stderr, "ricochet bench meet: {}: {} counted, {} frames ({:.1f} s CPU)\n", spec.name,
                       k_engines[e].name, stepped[e], cpu_now() - t0);
        }
        // The timed runs, the engines interleaved so that the machine's slow spells fall on all of them alike.
        for (int rep = 0; rep < reps; ++rep) {
            for (std::size_t e = 0; e < k_engine_count; ++e) {
                // An engine cut short once is not run again: one run past the budget says enough.
                if (!built[e] || (stepped[e] != 0 && stepped[e] < spec.frames)) continue;
                const std::unique_ptr<Engine> engine = k_engines[e].make(scene, false);
                const double t0 = cpu_now();
                std::int64_t f = 0;
                while (f < spec.frames && cpu_now() - t0 < budget) {
                    engine->step();
                    ++f;
                }
                ns[e].push_back((cpu_now() - t0) * 1e9 / (ball_count * static_cast<double>(f)));
                if (!spec.count) stepped[e] = f;
                if (!spec.count && rep == 0) notes[e] = engine->notes();
                fmt::print(stderr, "ricochet bench meet: {}: {} timed, run {} of {}\n", spec.name, k_engines[e].name,
                           rep + 1, reps);
            }
        }
        for (std::size_t e = 0; e < k_engine_count; ++e) {
            if (!built[e]) {
                table += fmt::format("| {} | {} | | not built | | | | | | | not found at build time |\n", label,
                                     k_engines[e].name);
                continue;
            }
            const Counts& c = counts[e];
            std::string note = notes[e];
            if (ns[e].size() == 1 && reps > 1) note += std::string(note.empty() ? "" : "; ") + "timed once: cut short";
            if (spec.count)
                table += fmt::format("| {} | {} | {} | {:.0f} | {} | {} | {} | {} | {} | {:+.1e}, {:.1e} | {} |\n", label,
                                     k_engines[e].name, stepped[e], median(ns[e]), c.overlaps, c.pass_throughs,
                                     c.pass_throughs == 0 ? "-" : fmt::format("{:.0f} %", 100.0 * c.deepest), c.unsure,
                                     c.escaped, c.energy_drift, c.energy_drift_max, note);
            else
                table += fmt::format("| {} | {} | {} | {:.0f} | | | | | | | {} |\n", label, k_engines[e].name,
                                     stepped[e], median(ns[e]), note);
            // robust decides every meet exactly: anything it left behind is a bug.
            if (e == 0 && (c.overlaps != 0 || c.pass_throughs != 0 || c.escaped != 0)) rc = 1;
        }
    }
    fmt::print("{}", table);
    if (rc != 0) fmt::print(stderr, "ricochet bench meet: robust left an overlap, an escape or a pass-through\n");
    return rc;
}

}  // namespace ricochet::meet_bench
