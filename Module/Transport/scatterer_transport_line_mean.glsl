//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 1 for a directional light, second draw (all layers in
// one): each texel's mean light, from what its line carried
// (scatterer_transport_lines.glsl): the light entering it, read from the slice before
// at q + e(z_q) where that slice holds T(q), times its mean factor; as
// scatterer_transport_sweep.glsl computes it slice by slice.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Sweep
in vec2 texCoord;
uniform sampler3D st_lines;      // per texel (T, mean factor), sweep order; its border reads 1
flat in float st_layer;          // this layer, the slice (scatterer_transport_layers_gs.glsl)
uniform vec3 st_lightToward;     // unit vector toward the light (world)
uniform float st_firstSlice;     // the sweep's first slice (nearest the light): T = 1

void main()
{
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_layer);
  float Tmean = 1.0;
  if (js.z != st_firstSlice)
  {
    vec3 stepSweep, stepGrid;
    float len;
    st_stepTowardLight(st_lightToward, stepSweep, stepGrid, len);
    vec3 qs = js + stepSweep;
    vec2 eq = st_sliceShift(qs.z, stepSweep.xy * stepSweep.z);
    float Tq = texture(st_lines, (vec3(qs.xy + eq, qs.z) + vec3(0.5)) / st_sweepDims).r;
    Tmean = Tq * texelFetch(st_lines, ivec3(js), 0).g;
  }
  gl_FragData[0] = vec4(st_storedTransmittance(Tmean, transpose(st_toSweep) * js));
}
