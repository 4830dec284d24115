//============================================================================
// The gather each fine texel takes (pass 0a, scatterer_transport_medium.glsl: -1 outside
// every material, its material m, or m + ST_MIXED) and whether it is a dense interior
// texel (the gather weights it down: scatterer_transport_gather.glsl), as its 8-bit
// texture holds them (R8, one byte a texel instead of 16-bit float channels beside the
// scattering coefficient): (g + 1 + 128 interior) / 255, exact for every g from -1 to
// 126 (g < 2 ST_MAX_MATERIALS = 16). Read by the count (0c) and the gather (2b).
//============================================================================
const float st_interiorBit = 128.0;

float st_storedGather(float g, bool interior)
{
  return (g + 1.0 + (interior ? st_interiorBit : 0.0)) / 255.0;
}

float st_gatherFrom(float stored)
{
  return mod(floor(stored * 255.0 + 0.5), st_interiorBit) - 1.0;
}

bool st_interiorFrom(float stored)
{
  return floor(stored * 255.0 + 0.5) >= st_interiorBit;
}
