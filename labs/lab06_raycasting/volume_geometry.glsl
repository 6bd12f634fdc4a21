// Lab 06: the volume's grid, for the modules that step one voxel or work in physical units.
#pragma once
#include "raycast_common.glsl"

// Physical distance between neighbouring voxel centres along x, y and z (gsv::Volume::spacing): voxels
// are rarely cubes, and differences per voxel along axes of different spacing are not comparable.
uniform vec3 uVoxelSpacing;

// Unset (0) or nonsensical spacing would divide by zero: treat the voxels as cubes of side 1.
vec3 rcVoxelSpacing() {
    return all(greaterThan(uVoxelSpacing, vec3(0.0))) ? uVoxelSpacing : vec3(1.0);
}

// One voxel along each axis, in texture coordinates.
vec3 rcVoxelStep() { return 1.0 / vec3(textureSize(uVolume, 0)); }

// Texture coordinates times this are physical units, where the gradients' directions are true.
vec3 rcPhysicalScale() { return vec3(textureSize(uVolume, 0)) * rcVoxelSpacing(); }
