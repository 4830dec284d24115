//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 1 for a directional light, second draw (every few draws
// of the lines, the layers of their slices): the light entering each texel, from what
// the lines carried (scatterer_transport_lines.glsl): T(q) st_farFactor(q), the light of
// the slice before and the factor of the step's far half from there to the texel's
// face, both interpolated at q + e(z_q), where that slice holds them for q; as
// scatterer_transport_sweep.glsl computes it slice by slice.
//
// The value of a texel depends on nothing but the lines, so the draw may take the
// texels in any order. ST_LINE_TEXELS_ARRIVING:
// - 0: into the transmittance texture, sweep order (the direct light, tests);
// - 1: the light's share of the light arriving, E_l T_l, straight into the arriving
//   light (grid order, one texel more a side, where T = 1; the lights added up by
//   blending): what pass 2a (scatterer_transport_arrive.glsl) computes for a
//   directional light from the transmittance texture, without that texture and pass.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Sweep
in vec2 texCoord;
// Per texel (T, st_farFactor) at the line's point, sweep order, a ring of slices
// (st_lineSlot); its border reads 1 (outside the grid no matter).
uniform sampler3D st_lines;
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform vec3 st_lightColor;      // ST_LINE_TEXELS_ARRIVING: E_l
uniform float st_firstSlice;     // the sweep's first slice (nearest the light): T = 1

// The light entering the texel at sweep position js (a texel of the grid).
float st_lineTexel(vec3 js)
{
  if (js.z == st_firstSlice)
  {
    return 1.0;
  }
  vec3 qs = js + st_stepSweep;
  vec2 eq = st_sliceShift(qs.z, st_stepSweep.xy * st_stepSweep.z);
  vec3 ring = vec3(st_sweepDims.xy, float(st_lineSlots));
  vec3 q = vec3(qs.xy + eq, float(st_lineSlot(qs.z)));
  vec2 keptAtQ = texture(st_lines, (q + vec3(0.5)) / ring).rg;
  return st_lightEnteringTexel(keptAtQ, transpose(st_toSweep) * js);
}

void main()
{
#if ST_LINE_TEXELS_ARRIVING
  vec3 j = vec3(floor(texCoord * (st_gridDims.xy + 2.0)), st_layer) - vec3(1.0);
  float T = 1.0; // outside the grid the light has crossed no matter
  if (all(greaterThanEqual(j, vec3(0.0))) && all(lessThan(j, st_gridDims)))
  {
    T = st_storedTransmittance(st_lineTexel(st_toSweep * j), j);
  }
  gl_FragData[0] = vec4(st_lightColor * T, 1.0);
#else
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_layer);
  gl_FragData[0] = vec4(st_storedTransmittance(st_lineTexel(js), transpose(st_toSweep) * js));
#endif
}
