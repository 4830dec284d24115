//============================================================================
// The light arriving unscattered at a grid position j, summed over the lights:
//   A(j) = sum_l E_l a_l(j) T_l(j)
// - T_l: light l's transmittance (pass 1);
// - E_l: its colour times intensity;
// - a_l(j): VTK's attenuation and spot cone of a positional light, 1 otherwise.
// The template gather (pass 2b) and the source of multiple scattering (pass 3a) are
// linear in each T_l with weights that do not depend on the light, so each reads A
// once for all lights instead of T_l once per light.
// - ST_ARRIVING (a build of several lights, or of one positional light): the lights
//   are summed into st_arriving, whose texture has one texel more than the grid on each
//   side, where the light has crossed no matter (T_l = 1, as the transmittance's
//   border): by pass 2a (scatterer_transport_arrive.glsl) from a light's transmittance,
//   or, for a directional light swept in parallel, by its own texels' draw
//   (scatterer_transport_line_texels.glsl). Then the passes read one texture per photon.
// - ST_DIRECT_LIGHT (a build of one directional light, a_l = 1): it is read here from
//   its transmittance, so that it costs no texture of the arriving light. Interpolating
//   E_l T_l is interpolating T_l, so A is the same either way.
//============================================================================
uniform sampler3D st_arriving;      // the lights of pass 2a, grid order
uniform sampler3D st_transmittance; // the direct light's T, sweep order (st_toSweep)
uniform vec3 st_directColor;        // the direct light's E_l

vec3 st_arrivingAt(vec3 j)
{
  vec3 A = vec3(0.0);
#if ST_ARRIVING
  A += texture(st_arriving, (j + vec3(1.5)) / (st_gridDims + 2.0)).rgb;
#endif
#if ST_DIRECT_LIGHT
  A += st_directColor * texture(st_transmittance, st_sweepCoord(j)).r;
#endif
  return A;
}

// A at texel j of the grid (an integer position inside it), read without filtering.
vec3 st_arrivingAtTexel(ivec3 j)
{
  vec3 A = vec3(0.0);
#if ST_ARRIVING
  A += texelFetch(st_arriving, j + ivec3(1), 0).rgb;
#endif
#if ST_DIRECT_LIGHT
  A += st_directColor * texelFetch(st_transmittance, ivec3(st_toSweep * vec3(j)), 0).r;
#endif
  return A;
}
