//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 0d, when the medium changes: both fluence atlases
// (scatterer_transport_atlas.glsl) start as no light (rgb 0), which the texels the
// diffusion leaves out keep (ScattererTransportTiles.h), and with each coarse texel's
// extinction sigma_t in alpha (pass 0b, scatterer_transport_coarsen.glsl; 0 where it holds
// no medium). The Jacobi passes write rgb alone, so a read of a neighbour's fluence brings
// its sigma_t, which the current through their common face takes
// (scatterer_transport_diffuse.glsl), in the same fetch.
//============================================================================
//VTK::Transport::Atlas
in vec2 texCoord;
uniform sampler3D st_coarseMedium; // coarse grid: rgb albedo, a sigma_t (pass 0b)

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
  float sigmaT = 0.0; // an atlas tile past the last layer
  if (z < int(st_coarseDims.z))
  {
    vec4 medium = texelFetch(st_coarseMedium, ivec3(pixel % layer, z), 0);
    sigmaT = st_holdsMedium(medium) ? medium.a : 0.0;
  }
  gl_FragData[0] = vec4(0.0, 0.0, 0.0, sigmaT);
}
