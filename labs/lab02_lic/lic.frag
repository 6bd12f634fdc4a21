// Lab 02 fragment stage: line integral convolution (Cabral and Leedom, 1993), after Bailey's listing.
// Each pixel averages the input image (white noise, or a photograph) along the streamline through it,
// uLength steps forward and uLength steps back: along the flow the samples agree and the streak
// survives; across it they are independent and the noise averages out.
#include "streamline.glsl"
#include "gsv/not_done.glsl"

uniform sampler2D uInput;  // the image to smear: white noise or a photograph
uniform int uLength;       // steps each way

in vec2 vTexCoord;
out vec4 fColor;

void main() {
    vec2 texel = 1.0 / vec2(textureSize(uFlow, 0));
    vec3 sum = texture(uInput, vTexCoord).rgb;
    float count = 1.0;  // the pixel's own sample: never a division by zero

    // TODO(L02-T1): follow the streamline forward: uLength steps with advance(st, +1.0, texel),
    // adding the input at each new point to sum and counting it, while streamlineContinues(st).
    vec2 st = vTexCoord;
    sum = kNotDone;

    // TODO(L02-T2): the same backwards. Bailey's listing steps forward in this second loop as
    // well, so every streak is one-sided: half the kernel counted twice.
    st = vTexCoord;
#ifndef STREAKS_FORWARD
#endif

    fColor = vec4(sum / count, 1.0);
}
