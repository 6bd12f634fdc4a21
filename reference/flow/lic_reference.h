#pragma once
// Line integral convolution along the EXACT streamlines of a continuous field: the reference lab 02's sweep
// measures its Euler and midpoint steps against. The GPU steps through a bilinear float texture with one Euler or
// midpoint step per sample; here each streamline is integrated in double with classical fourth-order Runge-Kutta
// (RK4) and kLicSubsteps substeps per unit step, through the analytic field itself (analytic_flow), so what
// remains of the error is the step's, not the reference's. Everything else is the GPU's rule: the pixel's own
// sample, then `length` samples at t = 1, 2, ... forward and the same backward, each direction ending at its first
// sample outside the grid, and the noise looked up as GL_LINEAR with GL_CLAMP_TO_EDGE looks it up.
// In reference/, the instructor's: linked by the solutions and the tests, never by a student's build.
#include "common/image/image.h"
#include "support/flow/flow_field.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

namespace gsv {

// RK4 substeps per unit step, chosen by measurement (tests/test_lic_reference.cpp). After 100 steps at speed 1 on a
// 64x64 grid, where the lab's vortex cores are fewest texels across, 8 and 32 substeps put every streamline within
// 8e-9 texels of each other on the vortices and 7e-10 on the double gyre (4 and 16: 1.3e-7 and 1.1e-8), and 8 are
// within 2e-12 texels of the closed form on the linear fields (2e-9 at the top speed of 4 texels a step). A noise
// sample moves by at most its distance in texels, so all of these are far below an 8-bit level (0.004); 8 rather
// than 4 for the margin at the top speed (8.6e-6 texels apart on the vortices at 64x64).
inline constexpr int kLicSubsteps = 8;

struct StreamlineOptions {
    // Unit speed: dx/ds = v / |v|, as the lab's `normalized` effect steps. Near a zero of the field the unit field
    // turns sharply, so there a substep is halved until it turns gently; a streamline that runs into a zero (the
    // source's centre, backwards) reaches it in finite arc length and ends there: it stays put, as the GPU's
    // safeNormalize stays put where v is exactly zero. Measured as above: 8 against 32 substeps within 1.9e-6 texels.
    bool normalized = false;
    int substeps = kLicSubsteps;
};

// Where the streamline of `velocity` through `start` (texel coordinates) is after `steps` unit steps of time (or of
// arc length when normalised); negative steps go backwards. It is not stopped at the grid's edge: the field's
// formulas go on beyond it. Throws gsv::Error for substeps < 1 or an empty `velocity`.
glm::dvec2 trace_streamline(const VelocityAt& velocity, glm::dvec2 start, int steps,
                            const StreamlineOptions& options = {});

// LIC of `noise` (width x height values, row 0 the bottom row, as gsv::white_noise makes them) along the exact
// streamlines of `velocity`, one image for each of `lengths` (steps each way, in any order), all from one walk per
// pixel up to the longest. Images are 8-bit grey, rounded as GL stores a colour (round(c * 255)), opaque, row 0 the
// TOP row like a framebuffer readback. Runs on every core. Throws gsv::Error naming the value for a size outside
// 1..8192, a noise of the wrong size, a negative length, substeps < 1 or an empty `velocity`.
std::vector<Image> exact_lic(const VelocityAt& velocity, const std::vector<float>& noise, int width, int height,
                             const std::vector<int>& lengths, const StreamlineOptions& options = {});

// exact_lic for one field and noise, a length at a time, as a sweep asks: each image is remembered (the sweep's
// curves, the GPU's steps, share the reference), and the streamlines are kept where the longest walk left them, so
// lengths asked for in increasing order cost one walk to the longest in all. A shorter length asked for later is
// walked afresh. Throws as exact_lic does, the sizes when constructed.
class ExactLic {
public:
    ExactLic() = default;
    ExactLic(VelocityAt velocity, std::vector<float> noise, int width, int height, StreamlineOptions options = {});

    const Image& image(int length);

private:
    // One half of a pixel's streamline (forward or backward) as far as it has been walked.
    struct Half {
        glm::dvec2 at{0.0};
        double sum = 0;      // of the samples so far, the pixel's own not included
        int count = 0;
        bool left = false;   // a sample fell outside the grid: the half is over
        bool ended = false;  // normalised, it ran into a zero of the field and stays there
    };
    void walk_to(int length);

    VelocityAt velocity_;
    std::vector<float> noise_;
    int width_ = 0, height_ = 0;
    StreamlineOptions options_;
    std::vector<Half> halves_;  // forward and backward for each pixel, row by row from the bottom
    int walked_ = 0;            // steps each way the halves have been walked
    std::map<int, Image> images_;
};

}  // namespace gsv
