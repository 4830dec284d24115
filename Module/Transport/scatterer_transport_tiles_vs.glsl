//VTK::System::Dec
//============================================================================
// Light transport volume: the vertex shader of the diffusion's passes (source and
// Jacobi), which draw only the coarse texels that hold a medium
// (ScattererTransportTiles.h), into the coarse grid's atlas
// (scatterer_transport_atlas.glsl). The vertices are the corners of the rectangles, two
// triangles each: texels [x0, x1) x [y0, y1) of layer z, drawn in layer z's tile. Their
// fragments get texCoord (in the layer) and st_layer as a full-screen quad's layer
// would (scatterer_transport_layers_gs.glsl).
//============================================================================
//VTK::Transport::Atlas
in vec4 ndCoordIn;  // the corner: (x, y) in texels, z its layer
in vec2 texCoordIn; // the corner's (x, y) again (the quad's two attributes are kept)
out vec2 texCoord;
flat out float st_layer;
uniform vec2 st_atlasSize; // the atlas drawn into, texels (DrawTiles sets it)

void main()
{
  vec2 atlas = vec2(st_atlasTexel(ivec3(0, 0, int(ndCoordIn.z + 0.5)))) + texCoordIn;
  gl_Position = vec4(2.0 * atlas / st_atlasSize - vec2(1.0), 0.0, 1.0);
  texCoord = texCoordIn / st_coarseDims.xy;
  st_layer = ndCoordIn.z;
}
