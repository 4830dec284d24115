//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 0c: counts, by an occlusion query around each layer's
// draw, the texels of the layer whose gather (pass 0a: -1 none, m, m + ST_MIXED) is at
// least st_atLeast; every other texel is discarded. Nothing is written (colour mask
// off). It tells which variant of the gather each layer needs.
//============================================================================
//VTK::Transport::StoredGather
in vec2 texCoord;
uniform sampler3D st_fineGather;
uniform vec3 st_gridDims;
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform float st_atLeast;

void main()
{
  ivec3 j = ivec3(ivec2(floor(texCoord * st_gridDims.xy)), int(st_layer));
  if (st_gatherFrom(texelFetch(st_fineGather, j, 0).r) < st_atLeast)
  {
    discard;
  }
  gl_FragData[0] = vec4(0.0);
}
