// Lab 03: the flow at the playhead, read from T time slices kept in one of three storages:
//   STORAGE_ARRAY    one GL_TEXTURE_2D_ARRAY, one layer per slice (the lesson)
//   STORAGE_VOLUME   one 3D texture, slices along r: filtering runs across slices too
//   STORAGE_SEPARATE T plain 2D textures, one texture unit each
#pragma once

uniform float uTime;  // the playhead, in [0, kPeriod]

// SLICES (T, compiled in, so the separate textures' sampler array has its exact size): slice k holds
// the flow at time k * kPeriod / T.
const float kPeriod = 10.0;

// An unfinished TODO sets this and the frame turns magenta.
bool gNotDone = false;

#if defined(STORAGE_ARRAY)
uniform sampler2DArray uFlowArray;
#elif defined(STORAGE_VOLUME)
uniform sampler3D uFlowVolume;
#else
uniform sampler2D uFlowSlices[SLICES];
#endif

// TODO(L03-T2): where the playhead falls on the slice axis, s in slice units (slice k at s = k).
// The time axis either wraps (TIME_WRAP_REPEAT: a periodic flow, after slice T - 1 comes slice 0)
// or stops at the last slice.
float sliceCoordinate(float time) {
    return 0.0;
}

// The slice after slice k in time.
int nextSlice(int k) {
#ifdef TIME_WRAP_REPEAT
    return (k + 1) % SLICES;
#else
    return min(k + 1, SLICES - 1);
#endif
}

// The slice nearest to s; on a wrapping axis the far half of the last slice is nearest to slice 0.
int nearestSlice(float s) {
    int k = int(floor(s + 0.5));
#ifdef TIME_WRAP_REPEAT
    return k % SLICES;
#else
    return min(k, SLICES - 1);
#endif
}

// The flow stored in slice k, at texture coordinate st.
vec2 flowInSlice(vec2 st, int k) {
#if defined(STORAGE_ARRAY)
    // TODO(L03-T3): look slice k up in the array. The third coordinate is the layer index itself,
    // not normalised like a 3D texture's r: GL rounds it to the nearest layer and never filters
    // between layers.
    gNotDone = true;
    return vec2(0.0);
#elif defined(STORAGE_VOLUME)
    // TODO(L03-T5): r is normalised: slice k's texels are centred at r = (k + 0.5) / T. Anywhere
    // else linear filtering blends in the neighbouring slice, and at r = 0 with GL_REPEAT the last
    // slice bleeds into the first.
    return texture(uFlowVolume, vec3(st, float(k) / float(SLICES))).xy;
#else
    // Indexing an array of samplers needs an index that is the same for the whole draw: k comes from
    // a uniform, so it is.
    return texture(uFlowSlices[k], st).xy;
#endif
}

#ifdef PLAYHEAD_SLICE
uniform float uSlice;  // s set directly: the slices looked up without the playhead's time (L03-T2)
#endif

vec2 flowAt(vec2 st) {
#if defined(PLAYHEAD_SLICE) && defined(TIME_WRAP_REPEAT)
    float s = mod(uSlice, float(SLICES));  // past the last slice a periodic axis blends into slice 0
#elif defined(PLAYHEAD_SLICE)
    float s = clamp(uSlice, 0.0, float(SLICES - 1));
#else
    float s = sliceCoordinate(uTime);
#endif
#if defined(BLEND_LINEAR) && defined(STORAGE_VOLUME)
    // The 3D texture's filter interpolates in time for free: one lookup between two slice centres
    // (the same filter that bleeds when a single slice is wanted).
    return texture(uFlowVolume, vec3(st, (s + 0.5) / float(SLICES))).xy;
#elif defined(BLEND_LINEAR)
    // TODO(L03-T4): blend linearly in time between the slice at or before s and the next one.
    return flowInSlice(st, nearestSlice(s));
#else
    return flowInSlice(st, nearestSlice(s));
#endif
}
