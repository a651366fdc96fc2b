// Tumble: tuning constants. Each says its unit, typical value and why.
// Lengths are in metres; Tumble is tuned for moving objects of 0.1 m to 10 m. A game that works in
// other length units (pixels, centimetres) sets tbSetLengthUnitsPerMeter before creating a world;
// the constants marked "× units" are then scaled by it (Box2D v3.2's scheme), the others are not.
#pragma once

#include "base.h"

// The length units (tbSetLengthUnitsPerMeter). Inside the library the constants read the stored
// value itself: a load where a call would spill every float register in the loops that use them,
// and the per-contact use (a body's speculative reach) is cached in the body. With both, a pile
// runs as many instructions as with the constants written as literals (Cachegrind), and the same
// trajectory bit for bit at 1.
#if defined(TUMBLE_BUILDING)
extern float tb_lengthUnitsPerMeter;
#define TB_LENGTH_UNITS tb_lengthUnitsPerMeter
#else
#define TB_LENGTH_UNITS tbGetLengthUnitsPerMeter()
#endif

/// Largest number of vertices of a convex polygon. 8 keeps tbPolygon small (cache) and covers
/// boxes, wedges and octagon approximations of round things.
#define TB_MAX_POLYGON_VERTICES 8

/// Linear slop, 0.005 m × units: the overlap the solver allows so that contacts stay persistent
/// (a resting box sits 0.005 m into the ground instead of chattering in and out of contact).
/// The speculative distance, the time-of-impact target and the recycling distance follow it.
#define TB_LINEAR_SLOP (0.005f * TB_LENGTH_UNITS)

/// Angular slop, 2 degrees in radians: the analogue of the linear slop for angles.
#define TB_ANGULAR_SLOP (2.0f / 180.0f * 3.14159265359f)

/// Speculative distance, 4 × linear slop = 0.02 m: manifold points are kept while the shapes are
/// up to this far apart, so the solver can stop an approach before it becomes a penetration.
#define TB_SPECULATIVE_DISTANCE (4.0f * TB_LINEAR_SLOP)

/// Speculative reach, 0.1 m × units: the least displacement per step that speculative contacts cover for
/// any body, however thin. A body's reach is max(TB_SPECULATIVE_REACH, TB_CONTINUOUS_FRACTION × its
/// thickness): its broad-phase box is swept by its predicted displacement up to its reach, the
/// narrow phase keeps points up to that much farther apart than TB_SPECULATIVE_DISTANCE, and only
/// motion beyond it is left to continuous collision.
#define TB_SPECULATIVE_REACH (0.1f * TB_LENGTH_UNITS)

/// Fat AABB margin, at most 0.05 m × units: a movable body's broad-phase box is its swept box enlarged by
/// min(TB_AABB_MARGIN, TB_AABB_MARGIN_FRACTION × its largest extent), so a body that rests or
/// jiggles moves no proxy. Larger means fewer proxy moves but more contacts (pairs whose boxes
/// overlap). Static boxes are not enlarged.
#define TB_AABB_MARGIN (0.05f * TB_LENGTH_UNITS)

/// Fat AABB margin relative to the body, 1/8 of its largest extent (0.022 m for a 0.25 m box,
/// capped at 0.05 m for a unit box), Box2D v3's fraction: with the sweep in the box, 1/16 made
/// markedly fewer contacts than v3 where bodies fly and tumble (smash, junkyard), while 1/8 keeps
/// every benchmark scene's contact count close to v3's at the same time per step
/// (docs/methods.md, "Broad-phase boxes").
#define TB_AABB_MARGIN_FRACTION 0.125f

/// Manifold recycling distance, at most TB_SPECULATIVE_DISTANCE = 0.02 m: a touching contact keeps
/// its manifold points (moved with the bodies, separations updated) while no point of one body can
/// have moved farther than this relative to the other since the narrow phase computed them. A
/// feature that was not in the manifold was then at least the speculative margin apart, so it
/// cannot reach contact unseen (contact.c, tbRecycleManifold). The default of each world's
/// distance (tbWorld_SetContactRecycleDistance).
#define TB_RECYCLE_DISTANCE TB_SPECULATIVE_DISTANCE

/// Manifold recycling angle, 2 degrees in radians (the angular slop): largest relative rotation of
/// the two bodies for which a manifold is carried along. The recycled manifold keeps its normal and
/// lever arms (contact.c, tbRecycleManifold, which also bounds each body's own turn).
#define TB_RECYCLE_ANGLE TB_ANGULAR_SLOP

/// Maximum position correction per step of the non-linear Gauss–Seidel pass, 0.2 m × units:
/// limits the push-out speed of deep overlaps (prevents popping).
#define TB_MAX_LINEAR_CORRECTION (0.2f * TB_LENGTH_UNITS)

/// Baumgarte factor, 0.2 (dimensionless): fraction of the penetration beyond the slop that the
/// velocity bias removes per step. Higher is stiffer and bouncier; Box2D 2.4 uses 0.2.
#define TB_BAUMGARTE 0.2f

/// Time a body must stay slow before its island may sleep, 0.5 s.
#define TB_TIME_TO_SLEEP 0.5f

/// Default linear sleep threshold, 0.05 m/s × units: a body slower than this counts as resting.
#define TB_LINEAR_SLEEP_TOLERANCE (0.05f * TB_LENGTH_UNITS)

/// Default angular sleep threshold, 2 degrees per second, in rad/s.
#define TB_ANGULAR_SLEEP_TOLERANCE (2.0f / 180.0f * 3.14159265359f)

/// Largest rotation of a body in one step, 0.25·π rad: keeps the linearised rotation integration
/// and the continuous-collision bounds valid.
#define TB_MAX_ROTATION (0.25f * 3.14159265359f)

/// A body is "fast" and gets swept for continuous collision when its motion in one step exceeds
/// what speculative contacts cover: max(TB_SPECULATIVE_REACH, this fraction × its extent, the
/// smallest distance from its centre of mass to its surface). 0.5: the speculative margin and the
/// broad-phase reach grow with speed up to that distance, so slower bodies are stopped by
/// speculative contacts and never tunnel.
#define TB_CONTINUOUS_FRACTION 0.5f

/// Conservative advancement stops when the shapes are within this separation, 0.25 × slop.
#define TB_TOI_TARGET_SEPARATION (0.25f * TB_LINEAR_SLOP)

/// Iteration cap of conservative advancement and of the root finders (never loop forever).
#define TB_TOI_MAX_ITERATIONS 30

/// Colours of the contact solver's constraint graph (src/solver/solver_types.h defines the same value for
/// the solver; a different one there would not compile with -Werror). Contacts that find no colour
/// go to an overflow, so tbGetGraphColor takes 0..TB_GRAPH_COLOR_COUNT, the last being the overflow
/// (Box2D v3.2 counts its overflow among its 24).
#define TB_GRAPH_COLOR_COUNT 24

/// Largest number of worlds that may exist at once.
#define TB_MAX_WORLDS 128

/// Most workers a world uses (tbWorldDef::workerCount): per-worker counters and buffers are sized by it.
#define TB_MAX_WORKERS 64

/// Most points tbDecomposePolygon takes: 1,024 (its checks and ear clipping cost O(n²); a longer
/// outline is terrain, for which segments or chains suit better).
#define TB_MAX_DECOMPOSE_POINTS 1024

/// A large length, 100 km × units: used as "infinity" for AABBs, ray lengths and joint lengths.
#define TB_HUGE (100000.0f * TB_LENGTH_UNITS)

/// Largest coordinate the API accepts, 1e6 (ten times TB_HUGE in metres; not scaled by the length
/// units, because the bounds below it are about float range): every vertex, centre and radius
/// of a shape in its body's frame, and a body's position. Beyond it a float's spacing exceeds
/// 6 cm, far coarser than the linear slop, and the products the collision layer forms (up to
/// the fourth power of a length, e.g. a·e − b² in segment distance) stay finite only while
/// lengths stay well below 1e9 m. See docs/limits.md.
#define TB_MAX_COORDINATE 1.0e6f

/// Largest world position the API accepts (a body's position, a query's origin): TB_MAX_COORDINATE,
/// or 1e9 m in the large-world build (TUMBLE_DOUBLE_PRECISION), where a double's spacing there is
/// 1.2e-7 m and shapes, measured from their bodies, stay within TB_MAX_COORDINATE of them.
#if defined(TUMBLE_DOUBLE_PRECISION)
#define TB_MAX_POSITION 1.0e9
#else
#define TB_MAX_POSITION TB_MAX_COORDINATE
#endif

/// Largest time step tbWorld_Step accepts, 1 s: a longer span is many frames and should be
/// stepped as many calls; a single step of it would move bodies by maximumLinearSpeed × Δt.
#define TB_MAX_TIME_STEP 1.0f

/// Smallest time step tbWorld_Step accepts, 1e-9 s. Below ~1e-38 s the sub-step's 1/h and the
/// angular speed bound TB_MAX_ROTATION/Δt overflow float (NaN positions); the bound keeps a wide
/// margin and is far below any useful step: in 1e-9 s a body at 1000 m/s moves 1e-6 m.
#define TB_MIN_TIME_STEP 1.0e-9f

/// Largest sub-step count tbWorld_Step accepts, 64 (4 is typical, 16 the most any benchmark
/// uses): the cost of a step is linear in it, and an untrusted scene must not hang a program.
#define TB_MAX_SUB_STEPS 64

/// Largest iteration count a world accepts (velocity, position and relax iterations), 64: the
/// same reason as TB_MAX_SUB_STEPS.
#define TB_MAX_ITERATIONS 64

/// Largest maximumLinearSpeed a world accepts, 1e6 m/s: a body then moves at most
/// 1e6 m/s × TB_MAX_TIME_STEP per step, so positions stay finite for any number of steps a
/// program can run.
#define TB_MAX_LINEAR_SPEED 1.0e6f

/// Largest mass of one shape, 1e24 kg (the Earth's is 6e24 kg): a density that gives more is
/// refused. Impulses scale with mass: at 5.6e36 kg a contact's angular impulse r × P overflowed
/// float and the body's velocity became NaN. With every shape below this bound, a body of fewer
/// than 2,000 shapes keeps r × P finite at any lever arm within TB_MAX_COORDINATE and any speed up
/// to twice the default maximumLinearSpeed, over all the sub-steps of a step.
#define TB_MAX_SHAPE_MASS 1.0e24f

/// Default collision category and mask bits.
#define TB_DEFAULT_CATEGORY_BITS 0x0000000000000001ULL
#define TB_DEFAULT_MASK_BITS 0xFFFFFFFFFFFFFFFFULL
