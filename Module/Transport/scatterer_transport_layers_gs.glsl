//VTK::System::Dec
//============================================================================
// Light transport volume: layered rendering. Each instance of the full-screen
// quad (scatterer_transport_layers_vs.glsl) goes to layer st_firstLayer +
// instance of the attached 3D textures (gl_Layer), so that a pass draws all the
// layers of its targets in one draw call instead of one draw (and one
// framebuffer change) per layer. The fragment shaders get the layer as
// st_layer and the quad's coordinates as texCoord, as they would from VTK's
// full-screen quad.
//============================================================================
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec2 st_quadCoord[];
flat in int st_instance[];
uniform int st_firstLayer;
out vec2 texCoord;
flat out float st_layer;

void main()
{
  int layer = st_firstLayer + st_instance[0];
  for (int i = 0; i < 3; ++i)
  {
    gl_Position = gl_in[i].gl_Position;
    texCoord = st_quadCoord[i];
    st_layer = float(layer);
    gl_Layer = layer;
    EmitVertex();
  }
  EndPrimitive();
}
