// What a starter draws where a TODO is still open: a colour no correct rendering produces.
#pragma once
const vec3 kNotDone = vec3(1.0, 0.0, 1.0);
