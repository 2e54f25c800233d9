/* ricochet/plugin.h: the plug-in interface, ABI version 2 (version 1, point balls only, still loads). Plain C
 * (C99 and C++), no other header of ricochet needed: build your own collision code as a shared library that
 * defines ricochet_plugin_entry, and every harness of ricochet runs against it without rebuilding ricochet:
 *
 *     ricochet run LOG --kernel plugin:./libmine.so          the run, as your code steps it
 *     ricochet fuzz --kernel plugin:./libmine.so             the fuzz campaign (workers load it by its absolute path)
 *     ricochet fuzz --kernel plugin:./libmine.so --target disc   its discs (with sweep_disc, below)
 *     RICOCHET_KERNEL=plugin:/abs/libmine.so ricochet_properties   the property suite
 *     ricochet replay --plugin ./libmine.so replays/         its saved failure logs
 *
 * The plug-in's kernel joins ricochet's kernel registry under the name it declares (kernel.hpp,
 * register_kernel): failure logs name that kernel (`kernel NAME`). Your code is held to ricochet's
 * guarantees, so a saved failure is a regression: its log carries no `expect failure` (kernel.hpp,
 * KernelOps::failures_documented, is false), replay fails it until the bug is fixed, and a campaign that
 * meets it again exits 1. A log never loads code: `kernel NAME` only finds a plug-in
 * already loaded from the command line (--kernel plugin:PATH, --plugin PATH) or RICOCHET_KERNEL.
 *
 * Conventions: those of every ricochet kernel, stated in core/include/ricochet/kernel.hpp ("Conventions
 * shared by every kernel"). In short, for the functions below:
 *   - A leg is the segment Bs -> Be with Be = Bs + v as C rounds it (the double nearest the sum); t is the
 *     fraction of the leg, in [0, 1]: B(t) = Bs + v*t, and a hit at t has its point B_i = B(t_i).
 *   - Touching is a collision: a leg ending exactly on a wall hits it (t = 1), a point on a circle's rim
 *     or a rectangle's edge or corner lies in it, shapes sharing a boundary point overlap.
 *   - A wall is the directed segment p0 -> p1, two-sided; its outward normal (e_y, -e_x), e = p1 - p0, points
 *     to the right of p0 -> p1 ("outside": classify > 0). A zero-length wall is never hit; a zero velocity
 *     sweeps nothing. A ball lying on a wall's line and moving off it does not hit that wall.
 *   - Numbers: every coordinate, radius and velocity component ricochet passes is finite, of magnitude at
 *     most 2^256 (kernel.hpp's accepted range).
 *   - Discs (ABI version 2): a disc of radius r is the set of points within r of its centre B(t); it touches a
 *     wall when its centre comes within r of the segment, a bumper (c, rb) when |B(t) - c| = r + rb. A contact
 *     normal points from the obstacle to the disc.
 * The harness judges your answers against ricochet's exact oracle by the checks of docs/scene-log.md
 * ("Checks"); a failure is saved as a scene log that `ricochet replay --plugin PATH LOG` reproduces.
 *
 * Threads: ricochet may call any function of the table from several threads at once (a scene's balls are
 * stepped in parallel, and some checks step a second copy alongside), always with arguments of its own:
 * the functions must be reentrant, and context is shared by all of them. Every call must be deterministic
 * (the same answer, bit for bit, for the same arguments): the checks step each frame again to trace it.
 *
 * Crashes and hangs: every call into the plug-in runs under a guard. A crash inside it (SIGSEGV, SIGBUS,
 * SIGFPE, SIGILL, SIGABRT) or a call that does not return within RICOCHET_PLUGIN_TIMEOUT seconds (default 5;
 * 0: no limit, for a debugger) ends the process with exit status 3 and a message naming the plug-in, the
 * function and its arguments; the scene being stepped is kept as a scene log (the message says where) and
 * replays the crash. A table that breaks this header (an unknown miss code, a hit on a wall that does not
 * exist, more hits than room; a disc hit whose t is not in [0, 1], whose B_i is not finite, or whose normal is zero
 * or not finite) is reported the same way.
 *
 * Versions: the loader calls ricochet_plugin_entry(RICOCHET_PLUGIN_ABI_VERSION), and again with 1 if that
 * returns NULL (a version-1 plug-in that serves only the version it was built for), and loads a table whose
 * abi_version is one it speaks, 1 or 2 (the error says which it got and which it speaks). Version 1 is the
 * table up to speed_abs_bound: point balls among walls; a version-1 plug-in built against the older header
 * keeps working unchanged, and a scene with discs or bumpers is refused for it as before. Version 2 appends
 * the disc functions (sweep_disc, sweep_disc_bumper, reflect_disc). Within one ABI version the table only
 * grows at its end: struct_size says how much of it the plug-in knows, and the loader takes every field past
 * it as absent (NULL, 0); a version-1 table never has the disc functions, whatever its struct_size. */
#ifndef RICOCHET_PLUGIN_H
#define RICOCHET_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The ABI this header describes; the loader loads tables of this version and of version 1, and refuses others. */
#define RICOCHET_PLUGIN_ABI_VERSION 2u
/** The one symbol the loader looks up (dlsym) in the shared library. */
#define RICOCHET_PLUGIN_ENTRY_SYMBOL "ricochet_plugin_entry"
/** Most bytes of a kernel name: 1 to 64 of A-Z a-z 0-9 '-' '_' '.', and not a name already taken. */
#define RICOCHET_PLUGIN_MAX_NAME 64
/** Most bounces in one frame (kernel.hpp's k_max_bounces): the room a frame step has for hits. */
#define RICOCHET_PLUGIN_MAX_BOUNCES 16

/** A point or vector, y up. */
typedef struct ricochet_vec2 {
    double x;
    double y;
} ricochet_vec2;

/** A two-sided wall: the directed segment p0 -> p1. */
typedef struct ricochet_wall {
    ricochet_vec2 p0;
    ricochet_vec2 p1;
} ricochet_wall;

/** A static circle with centre c and radius r >= 0. */
typedef struct ricochet_circle {
    ricochet_vec2 c;
    double r;
} ricochet_circle;

/** An axis-aligned rectangle, y up: left <= right, bottom <= top. */
typedef struct ricochet_rect {
    double left;
    double bottom;
    double right;
    double top;
} ricochet_rect;

/** A point ball at pos moving vel per frame. */
typedef struct ricochet_ball {
    ricochet_vec2 pos;
    ricochet_vec2 vel;
} ricochet_ball;

/** A sweep's answer (ricochet_sweep_result.miss): a hit, or why the leg misses. Giving a reason is optional:
 * RICOCHET_MISS says "no hit" and nothing more, and the oracle then only asks whether the wall is hit. A
 * reason given is checked exactly: the lecture's five tests in order (sweep.hpp, Miss), then the
 * degenerate cases. */
enum {
    RICOCHET_HIT = 0,                /**< the leg hits the wall */
    RICOCHET_MISS_BOTH_INSIDE = 1,   /**< test 1: both ends strictly inside (BC < 0) */
    RICOCHET_MISS_BOTH_OUTSIDE = 2,  /**< test 2: both ends strictly outside (BC > 0) */
    RICOCHET_MISS_PARALLEL = 3,      /**< test 3: moving along the wall's line */
    RICOCHET_MISS_BEFORE_P0 = 4,     /**< test 4: the line is crossed before p0 */
    RICOCHET_MISS_PAST_P1 = 5,       /**< test 5: the line is crossed past p1 */
    RICOCHET_MISS_DEGENERATE = 6,    /**< a zero-length wall or a zero velocity */
    RICOCHET_MISS_LEAVING = 7,       /**< Bs lies on the wall's line and the ball moves off it */
    RICOCHET_MISS = 8                /**< no hit, reason not given */
};

/** What sweep answers for one leg against one wall. */
typedef struct ricochet_sweep_result {
    int32_t miss;        /**< RICOCHET_HIT, or a RICOCHET_MISS_* code, or RICOCHET_MISS */
    double t;            /**< with a hit: t_i in [0, 1], the fraction of the leg where it meets the wall */
    ricochet_vec2 point; /**< with a hit: B_i, the point where it meets the wall */
} ricochet_sweep_result;

/** What sweep_disc and sweep_disc_bumper answer for one leg of a disc against one obstacle (ABI version 2). */
typedef struct ricochet_disc_result {
    int32_t miss;         /**< RICOCHET_HIT, or a miss: RICOCHET_MISS (a RICOCHET_MISS_* code reads as RICOCHET_MISS:
                               a disc's miss has no reason the oracle checks) */
    double t;             /**< with a hit: t_i in [0, 1], the fraction of the leg where the disc first touches */
    ricochet_vec2 point;  /**< with a hit: B_i, the disc's centre at that contact (finite) */
    ricochet_vec2 normal; /**< with a hit: the contact normal, from the obstacle to the disc (the face's side the
                               disc is on, B_i - P_k at a cap, B_i - C at a bumper): finite and non-zero, of any
                               length (it is only a direction) */
} ricochet_disc_result;

/** One bounce of a frame step: the wall (its index in the frame's walls), the frame time and the point. */
typedef struct ricochet_hit {
    uint32_t wall;       /**< index into ricochet_frame.walls */
    double t;            /**< the time within the frame, in [0, 1] */
    ricochet_vec2 point; /**< B_i, the point it bounced off the wall at */
} ricochet_hit;

/** How a frame step ended (ricochet_frame.status). */
enum {
    RICOCHET_FRAME_OK = 0,           /**< the ball finished its frame */
    RICOCHET_FRAME_BOUNCE_LIMIT = 1  /**< RICOCHET_PLUGIN_MAX_BOUNCES bounces: the ball stays at its last hit point */
};

/** One ball's frame for a whole-frame step: ricochet fills the inputs, the plug-in the outputs. */
typedef struct ricochet_frame {
    ricochet_ball ball;          /**< in: the ball before the frame; out: after it */
    const ricochet_wall* walls;  /**< in: every wall of the scene */
    uint32_t wall_count;         /**< in: how many */
    uint32_t hit_capacity;       /**< in: room in hits (RICOCHET_PLUGIN_MAX_BOUNCES) */
    ricochet_hit* hits;          /**< out: the frame's bounces in order */
    uint32_t hit_count;          /**< out: how many (at most hit_capacity); 0 on entry */
    uint32_t reflections;        /**< out: every reflection of v this frame, hits and extra corner ones (the
                                      `speed` check allows this many reflections' change of |v|); 0 on entry */
    int32_t status;              /**< out: RICOCHET_FRAME_OK or RICOCHET_FRAME_BOUNCE_LIMIT; OK on entry */
} ricochet_frame;

/** The plug-in's table: what ricochet_plugin_entry returns. Every function receives context (what init set,
 * else NULL) first. A NULL optional function is supplied by ricochet from the robust kernel (exact
 * decisions, kernel.hpp), so the harness judges only the code you provide. */
typedef struct ricochet_plugin {
    /** RICOCHET_PLUGIN_ABI_VERSION as the plug-in was built. */
    uint32_t abi_version;
    /** sizeof(ricochet_plugin) as the plug-in was built: fields past it are taken as absent. */
    uint32_t struct_size;
    /** The kernel's name, as scene logs and --kernel spell it (RICOCHET_PLUGIN_MAX_NAME); copied at load. */
    const char* name;
    /** Optional: called once after loading; sets *context (NULL before). Non-zero return: loading fails. */
    int32_t (*init)(void** context);
    /** Optional: called once when the process ends normally, with the context init set. */
    void (*destroy)(void* context);
    /** Required: the leg bs -> bs + v against wall. Fills out: a hit with t and point, or a miss. Used by
     * ricochet's frame loop (below) and, on their own, by the checks that probe single sweeps. */
    void (*sweep)(void* context, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* wall,
                  ricochet_sweep_result* out);
    /** Optional: the bounce off wall, v' (robust's if NULL). The `speed` check holds it to |v'| = |v| within
     * speed_rel_bound*|v| + speed_abs_bound. */
    ricochet_vec2 (*reflect)(void* context, ricochet_vec2 v, const ricochet_wall* wall);
    /** Optional: the side of p against wall's line: > 0 outside, < 0 inside, 0 on it (its sign is read). */
    int32_t (*classify)(void* context, ricochet_vec2 p, const ricochet_wall* wall);
    /** Optional: non-zero if p lies in circle c (|cp| <= r). */
    int32_t (*point_in_circle)(void* context, ricochet_vec2 p, const ricochet_circle* c);
    /** Optional: non-zero if circles a and b overlap (|ca - cb| <= ra + rb). */
    int32_t (*circles_overlap)(void* context, const ricochet_circle* a, const ricochet_circle* b);
    /** Optional: non-zero if p lies in rectangle r. */
    int32_t (*point_in_rect)(void* context, ricochet_vec2 p, const ricochet_rect* r);
    /** Optional: non-zero if rectangles a and b overlap. */
    int32_t (*rects_overlap)(void* context, const ricochet_rect* a, const ricochet_rect* b);
    /** Optional: one ball's whole frame among the walls, your own frame loop. Without it ricochet steps the
     * frame with your sweep and reflect the lecture's way: the earliest hit over every wall but the one just
     * bounced off (the lowest index on a tie), bounce at B_i, then the rest of the frame, the leg from B_i
     * to B_i + (1 - t_i)*v', at most RICOCHET_PLUGIN_MAX_BOUNCES times, as the lecture kernels do; it traces every
     * leg, so the checks judge each sweep. With it, the checks see only the frame's result: they compare its
     * first hit with the exact kernel's, and skip what needs the legs (the per-leg decisions, `accuracy`). */
    void (*step)(void* context, ricochet_frame* frame);
    /** The bound reflect keeps (the `speed` check): | |v'| - |v| | <= speed_rel_bound*|v| + speed_abs_bound
     * per reflection. Both 0: robust's bound (2^-48 relative, 2^-1068 absolute). */
    double speed_rel_bound;
    /** See speed_rel_bound. */
    double speed_abs_bound;

    /* ABI version 2: discs. Everything above is version 1, unchanged. */

    /** Optional: the leg bs -> bs + v of a disc of radius r against wall, its face and its two end caps (the
     * points within r of the segment p0 -> p1); r > 0, or r = 0 for a point ball in a scene with bumpers (then the
     * wall's segment itself). Fills out: RICOCHET_HIT with the earliest contact (t, the centre B_i, the normal
     * from the wall to the disc), or RICOCHET_MISS. ricochet's conventions for discs (docs/scene-log.md, "Discs and
     * bumpers"): a contact is an entry (the distance reaches r while decreasing; a tangent is no hit); a disc that
     * starts in reach hits at t = 0 if it moves closer, else not; a zero-length wall is never hit (its caps
     * included); a zero velocity sweeps nothing. With it, ricochet steps discs with this plug-in: its frame loop
     * (the lecture's: every wall and bumper but the one just bounced off, the earliest t, ties to the lowest wall
     * then the lowest bumper, the bounce about the returned normal at the returned B_i, the rest of the frame
     * from B_i, at most RICOCHET_PLUGIN_MAX_BOUNCES bounces) traces every leg, so the checks judge each answer.
     * Without it the plug-in's kernel steps point balls among walls only (discs and bumpers are refused). A
     * whole-frame step (above) is for point balls only: discs always go through this frame loop. */
    void (*sweep_disc)(void* context, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_wall* wall,
                       ricochet_disc_result* out);
    /** Optional (with sweep_disc): the same leg against a solid bumper, the circle (c, bumper->r): a contact
     * where |B(t) - c| = r + bumper->r, entering; the normal from c to the disc. A bumper of radius 0 met by a
     * point (r = 0) is never hit. Without it the kernel steps discs among walls only, and a scene with bumpers
     * is refused. */
    void (*sweep_disc_bumper)(void* context, ricochet_vec2 bs, ricochet_vec2 v, double r,
                              const ricochet_circle* bumper, ricochet_disc_result* out);
    /** Optional: the bounce of a disc, v' for v about the contact normal a sweep returned (as returned: not
     * necessarily of unit length). NULL: robust's reflection, v - 2(v.n^)n^ with n^ = normal/|normal|. Held to
     * the same `speed` bound as reflect. */
    ricochet_vec2 (*reflect_disc)(void* context, ricochet_vec2 v, ricochet_vec2 normal);

    /* Room to grow within version 2: the functions still to come (a ball meeting a ball) are appended here, and
     * a plug-in built before them has a struct_size that ends before them, so it reads as not having them. */
} ricochet_plugin;

/** The entry the loader looks up: returns the plug-in's table, which must stay valid while the process
 * runs (a static one), or NULL if it cannot serve. abi_version is the version the loader speaks; return a
 * table of that version, or of your own, and the loader says they differ. */
typedef const ricochet_plugin* (*ricochet_plugin_entry_fn)(uint32_t abi_version);

#if defined(__GNUC__) || defined(__clang__)
/** Exports the entry from a library built with -fvisibility=hidden. */
#define RICOCHET_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define RICOCHET_PLUGIN_EXPORT
#endif

/** Define this in the plug-in (ricochet itself only looks it up). */
RICOCHET_PLUGIN_EXPORT const ricochet_plugin* ricochet_plugin_entry(uint32_t abi_version);

#ifdef __cplusplus
}
#endif

#endif /* RICOCHET_PLUGIN_H */
