// The exact kernel's disc: the shared disc frame (disc/frame.hpp) with robust's exact decisions (contact.hpp) and
// every construction correctly rounded from its exact value (disc/nearest.cpp). Unlike exact's point balls
// (exact_kernel.cpp, an independent oracle) the decisions here are robust's own code: for discs the independent
// check is disc_contact_test's comparison with a 512-bit computation, and exact differs from robust only in
// rounding.
#include <vector>

#include "kernels/disc/frame.hpp"
#include "kernels/exact/exact_kernel.hpp"

namespace ricochet {

FrameStatus ExactKernel::step_disc(Ball& ball, BallMemory& /*memory*/, const Obstacles& obstacles,
                                   std::vector<HitEvent>& hits, StepScratch& scratch) {
    return disc::step_frame(ball, obstacles, hits, scratch, {&disc::nearest_contact_point, &disc::nearest_reflection});
}

}  // namespace ricochet
