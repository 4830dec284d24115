//VTK::System::Dec
//============================================================================
// Light transport volume: the vertex shader of the diffusion's passes (source and
// Jacobi), which draw only the coarse texels that hold a medium
// (ScattererTransportTiles.h). Instance i of the quad is rectangle i of st_tileRects:
// texels [x0, x1) x [y0, y1) of layer z. It goes there as the full-screen quad's
// instance goes to its layer (scatterer_transport_layers_gs.glsl, with st_firstLayer
// 0), and its fragments get texCoord and st_layer as the full-screen quad's would.
//============================================================================
in vec4 ndCoordIn;
in vec2 texCoordIn;
uniform sampler2D st_tileRects; // 2 texels a rectangle: (x0, y0, x1, y1), (z, 0, 0, 0)
uniform int st_rowRects;        // rectangles a row of st_tileRects
uniform vec2 st_tileDims;       // a layer's texels (columns, rows)
out vec2 st_quadCoord;
flat out int st_instance;

void main()
{
  ivec2 at = ivec2(2 * (gl_InstanceID % st_rowRects), gl_InstanceID / st_rowRects);
  vec4 rect = texelFetch(st_tileRects, at, 0);
  float z = texelFetch(st_tileRects, at + ivec2(1, 0), 0).r;
  // The quad's corner, (0, 0) to (1, 1): x from its position, y from its texture
  // coordinate, so that the program keeps both attributes vtkOpenGLQuadHelper binds.
  vec2 corner = vec2(ndCoordIn.x * 0.5 + 0.5, texCoordIn.y);
  vec2 t = mix(rect.xy, rect.zw, corner) / st_tileDims;
  gl_Position = vec4(2.0 * t - vec2(1.0), 0.0, 1.0);
  st_quadCoord = t;
  st_instance = int(z + 0.5);
}
