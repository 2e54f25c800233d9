// Cutting entities out of a failing scene: delta debugging over balls, walls, circles and rects, with the
// free hints a run gives first (passes.hpp).
//
// The delta debugging is ddmin's complement step alone, as C-Reduce and Lithium do it: remove chunks of
// size n (all of them), then ⌈n/2⌉, …, 1, sweeping left to right; a removal that still fails is kept and the
// sweep goes on at the same place. A failure that needs k entities of n costs about 2k·log2(n) tries, and
// each try runs a scene no larger than the last one that failed.
#include <algorithm>
#include <set>
#include <type_traits>

#include "reduce/passes.hpp"

namespace ricochet::detail::reduce {
namespace {

/// Removes entities [i, end) of items; a ball takes its mass with it, so that masses stay one per ball.
template <class T>
void erase_range(Scene& s, std::vector<T> Scene::*items, std::size_t i, std::size_t end) {
    std::vector<T>& v = s.*items;
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(i), v.begin() + static_cast<std::ptrdiff_t>(end));
    if constexpr (std::is_same_v<T, Ball>)
        if (!s.masses.empty())
            s.masses.erase(s.masses.begin() + static_cast<std::ptrdiff_t>(i),
                           s.masses.begin() + static_cast<std::ptrdiff_t>(end));
}

template <class T>
void cut_chunks(Trials& trials, std::vector<T> Scene::*items, std::string_view pass) {
    std::size_t chunk = (trials.current().scene.*items).size();
    while (chunk > 0) {
        for (std::size_t i = 0; i < (trials.current().scene.*items).size();) {
            if (trials.spent()) return;
            Scene candidate = trials.current().scene;
            const std::size_t end = std::min(i + chunk, (candidate.*items).size());
            erase_range(candidate, items, i, end);
            // Kept: the entities after the chunk are now at i. Not kept: on past the chunk.
            if (!trials.attempt(std::move(candidate), pass)) i = end;
        }
        if (chunk == 1) break;
        chunk = (chunk + 1) / 2;
    }
}

/// The ball the current failure (or step error) names.
std::uint32_t failing_ball(const Failing& f) { return f.failure ? f.failure->ball : f.error ? f.error->ball : 0; }

}  // namespace

void cut_balls(Trials& trials) {
    const Failing& now = trials.current();
    const std::uint32_t b = failing_ball(now);
    // The failing ball alone: most failures are one ball's.
    if (now.scene.balls.size() > 1 && b < now.scene.balls.size()) {
        Scene candidate = now.scene;
        candidate.balls = {now.scene.balls[b]};
        if (!now.scene.masses.empty()) candidate.masses = {now.scene.masses[b]};
        trials.attempt(std::move(candidate), "balls");
    }
    cut_chunks(trials, &Scene::balls, "balls");
}

void cut_walls(Trials& trials) {
    if (trials.current().scene.walls.size() > 1) {
        // What the run names, for free: the wall a no-tunnel piece went through, and the walls hit.
        const std::uint32_t ball = failing_ball(trials.current());
        const std::int64_t frame = trials.current().frame();
        std::set<std::uint32_t> piece;
        if (const auto& f = trials.current().failure; f && f->piece) piece.insert(f->piece->wall);
        std::set<std::uint32_t> hit_then = piece;  // the piece's wall and the failing ball's hits in the failing frame
        std::set<std::uint32_t> hit_ever = piece;  // the piece's wall and every wall any ball hit
        const bool ran = trials.observe(
            [&](std::span<const Event> events) {
                for (const Event& e : events) {
                    if (e.kind != Event::Kind::hit) continue;
                    hit_ever.insert(e.index);
                    if (e.ball == ball && e.frame == frame) hit_then.insert(e.index);
                }
            },
            "walls");
        // Each set holds the one before; the first that still fails is the smallest of them.
        std::size_t tried = 0;
        for (const std::set<std::uint32_t>* keep : {&piece, &hit_then, &hit_ever}) {
            if (!ran || keep->empty() || keep->size() == tried || keep->size() >= trials.current().scene.walls.size())
                continue;
            tried = keep->size();
            Scene candidate = trials.current().scene;
            candidate.walls.clear();
            for (const std::uint32_t w : *keep) candidate.walls.push_back(trials.current().scene.walls[w]);
            if (trials.attempt(std::move(candidate), "walls")) break;
        }
    }
    cut_chunks(trials, &Scene::walls, "walls");
}

void cut_statics(Trials& trials) {
    cut_chunks(trials, &Scene::circles, "circles");
    cut_chunks(trials, &Scene::rects, "rects");
    cut_chunks(trials, &Scene::bumpers, "bumpers");
}

}  // namespace ricochet::detail::reduce
