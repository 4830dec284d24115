//============================================================================
// The gather each fine texel takes (pass 0a, scatterer_transport_medium.glsl: -1 outside
// every material, its material m, or m + ST_MIXED) as its 8-bit texture holds it (R8,
// one byte a texel instead of a 16-bit float channel beside the scattering
// coefficient): (g + 1) / 255, exact for every g from -1 to 254. Read by the count
// (0c) and the gather (2b).
//============================================================================
float st_storedGather(float g)
{
  return (g + 1.0) / 255.0;
}

float st_gatherFrom(float stored)
{
  return floor(stored * 255.0 + 0.5) - 1.0;
}
