//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 0d, when the medium changes: both fluence atlases
// (scatterer_transport_atlas.glsl) start as no light (rgb 0), which the texels the
// diffusion leaves out keep (ScattererTransportTiles.h), and with the ambient occlusion
// of pass 0b (scatterer_transport_coarsen.glsl) in alpha. The Jacobi passes write rgb
// alone, so the gather reads the multiply scattered light and the occlusion together,
// in one interpolated read (scatterer_transport_scattered.glsl).
//============================================================================
//VTK::Transport::Atlas
in vec2 texCoord;
uniform sampler3D st_occlusion; // coarse grid: the ambient light's transmittance (pass 0b)

void main()
{
  // texCoord is read only to keep the attribute VTK's quad binds; it never exceeds 1.
  if (texCoord.x > 2.0)
  {
    discard;
  }
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 layer = ivec2(st_coarseDims.xy);
  int z = (pixel.y / layer.y) * st_atlasColumns + pixel.x / layer.x;
  float occlusion = 0.0; // an atlas tile past the last layer
  if (z < int(st_coarseDims.z))
  {
    occlusion = texelFetch(st_occlusion, ivec3(pixel % layer, z), 0).r;
  }
  gl_FragData[0] = vec4(0.0, 0.0, 0.0, occlusion);
}
