#pragma once
// A picture reduced to what tells one wrong picture from another (issue 40: the known mistakes a student edition
// ships, grader/golden/<lab>/mistakes.*): per block of pixels its mean colour, and how its brightness changes across
// x and across y and how the two go together (the structure tensor). The means keep where a picture is lit and how;
// the tensor keeps texture a mean would average away: a line integral convolution's streaks are an even grey on
// average, their direction is in the tensor. At most 32 blocks along the longer side, twice over.
#include "common/image/image.h"

namespace gsv {

struct PictureSignature {
    int block = 0;             // pixels per block side
    Image colour;              // each block's mean RGB (alpha 255)
    Image texture;             // R: rms of d/dx, G: rms of d/dy of the brightness, B: their correlation, 0..255
    bool empty() const { return colour.empty(); }
};

// The block side for a picture of this size: at most 32 blocks along its longer side.
int signature_block(int width, int height);

// Throws gsv::Error where `block` is not positive or the image is empty.
PictureSignature picture_signature(const Image& image, int block);

// The mean absolute difference of two signatures over their six channels, in levels of 255. Throws gsv::Error where
// their sizes differ.
double signature_distance(const PictureSignature& a, const PictureSignature& b);

// Whether `picture` is `mistake`'s rather than anything else: nearer to it than a third of the way from the mistake to
// the golden (so nearer the mistake than the golden by far), and the mistake's picture differs from the golden's in
// its signature at all.
bool signature_matches(const PictureSignature& picture, const PictureSignature& mistake, const PictureSignature& golden);

// Two mistakes made together, guessed from their pictures alone (no picture of them together is shipped): each block's
// change from the golden added (a highlight and a darker ambient), or, for the colour, the two ratios to the golden
// multiplied (a band's colour times the shading). Throws gsv::Error where the sizes differ.
enum class Composition { Added, Multiplied };
PictureSignature composed_signature(const PictureSignature& first, const PictureSignature& second, const PictureSignature& golden,
                                    Composition how);

// The colour thumbnail scaled up to width x height (bilinear) to be shown beside full-size pictures.
Image signature_picture(const PictureSignature& signature, int width, int height);

}  // namespace gsv
