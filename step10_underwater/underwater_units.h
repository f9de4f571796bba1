// The texture units step10 adds to step06's (step06_foam_sky/texture_units.h), read by the C++ and
// the GLSL alike.
#ifndef STEP10_UNDERWATER_UNITS_H
#define STEP10_UNDERWATER_UNITS_H
#define UNIT_CAUSTICS 12  // the sunlight the waves focus on the seabed (u_caustics)
#define UNIT_CAUSTIC_RAYS 13         // the caustics' rays: where each came from and landed (u_rays)
#define UNIT_CAUSTIC_TRANSMITTED 14  // and the share of its light the surface let through (u_transmitted)
#define UNIT_BELOW_PICTURE 15  // the picture below the surface, put under the waterline (waterline.frag)
#endif
