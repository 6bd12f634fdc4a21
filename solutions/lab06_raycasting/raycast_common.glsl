// Lab 06: what the ray-casting skeleton and every module share. Positions are volume texture
// coordinates, [0, 1]^3 over the volume, the space the entry and exit textures hold.
#pragma once

uniform sampler3D uVolume;  // the scalar volume: R32F, linear filtering, clamp to edge, values in [0, 1]
uniform float uStepSize;    // wanted distance between samples, in texture coordinates (from samples per voxel)

// Rays longer than this many samples take a longer step: a tiny uStepSize must not hang the GPU.
const int kRcMaxSamples = 16384;

// One ray through the volume.
struct RcRay {
    vec3 entry;
    vec3 direction;  // unit length
    float tEnd;      // the exit's ray parameter: the distance from entry to exit (not "length": glslang
                     // reads .length as the array method)
    // The ray is cut into `samples` equal segments of length `step` (close to uStepSize), sampled at their
    // midpoints: every segment is whole, so opacity correction needs no special last segment.
    float step;
    int samples;
};

vec3 rcPosition(RcRay ray, float t) { return ray.entry + t * ray.direction; }

// What compositing carries along a ray; each compositing module reads the fields it needs.
struct RcState {
    vec4 color;  // premultiplied by alpha
    float hitT;  // the ray parameter whose depth is written; negative: no hit yet
    float value; // the module's scalar: the largest intensity (MIP), the previous sample's (isosurface), the
                 // opacity correction's exponent (DVR: the same for every sample of the ray)
};

// Nothing gathered, no hit. A compositing module's rcStart... begins each ray from this.
RcState rcStartState() { return RcState(vec4(0.0), -1.0, 0.0); }
