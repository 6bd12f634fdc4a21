// A tone curve applied to an image after it is drawn (LIC's optional contrast, support/flow/lic_contrast.h): every
// channel through the same monotone map, piecewise linear between the curve's values. The interpolation is done
// here in float, between two exact texel fetches: a GPU's filtering would round its weights to 8 bits or so, and a
// stretch multiplies that rounding.
uniform sampler2D uImage;      // the image, one texel per pixel
uniform sampler2D uToneCurve;  // the curve's values in the red channel, one row
uniform vec2 uToneRange;       // the grey levels of the curve's first and last value; an empty range: no change

out vec4 fColor;

float toned(float grey) {
    // NaN stays NaN, so that the lab's check for non-finite pixels still sees it.
    if (isnan(grey) || !(uToneRange.y > uToneRange.x)) return grey;
    int last = textureSize(uToneCurve, 0).x - 1;
    float position = clamp((grey - uToneRange.x) / (uToneRange.y - uToneRange.x), 0.0, 1.0) * float(last);
    int i = min(int(position), last - 1);
    float below = texelFetch(uToneCurve, ivec2(i, 0), 0).r;
    float above = texelFetch(uToneCurve, ivec2(i + 1, 0), 0).r;
    return mix(below, above, position - float(i));
}

void main() {
    vec4 color = texelFetch(uImage, ivec2(gl_FragCoord.xy), 0);
    fColor = vec4(toned(color.r), toned(color.g), toned(color.b), color.a);
}
