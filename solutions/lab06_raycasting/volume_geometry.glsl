// Lab 06: the volume's grid, for the modules that step one voxel or work in physical units.
#pragma once
#include "raycast_common.glsl"
// The skeleton calls rcPrepareVolumeGeometry() before its loop where this file is included.
#define RC_HAS_VOLUME_GEOMETRY 1

// Physical distance between neighbouring voxel centres along x, y and z (gsv::Volume::spacing): voxels
// are rarely cubes, and differences per voxel along axes of different spacing are not comparable.
uniform vec3 uVoxelSpacing;

// The grid's figures are the same for every sample, so they are worked out once per ray: computed in each
// module's call, per sample, they and DVR's exponent made the assembled ray caster 4 to 6% slower than the
// hand-written one, which hoists them (llvmpipe leaves textureSize in the loop); once per ray, 0.97 to 1.01.
vec3 rcGridSpacing;
vec3 rcGridVoxelStep;
vec3 rcGridPhysicalScale;

void rcPrepareVolumeGeometry() {
    // Unset (0) or nonsensical spacing would divide by zero: treat the voxels as cubes of side 1.
    rcGridSpacing = all(greaterThan(uVoxelSpacing, vec3(0.0))) ? uVoxelSpacing : vec3(1.0);
    vec3 size = vec3(textureSize(uVolume, 0));
    rcGridVoxelStep = 1.0 / size;
    rcGridPhysicalScale = size * rcGridSpacing;
}

vec3 rcVoxelSpacing() { return rcGridSpacing; }

// One voxel along each axis, in texture coordinates.
vec3 rcVoxelStep() { return rcGridVoxelStep; }

// Texture coordinates times this are physical units, where the gradients' directions are true.
vec3 rcPhysicalScale() { return rcGridPhysicalScale; }
