#version 330 core
// Lit triangle meshes in the sensor frame S (mm): the deformation surface and
// the 6-D input object. u_model places the mesh, u_view_projection is the
// panel's camera; normals are transformed by the model's rotation part.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_colour;
layout(location = 3) in float a_scalar;
uniform mat4 u_model;
uniform mat4 u_view_projection;
out vec3 v_normal;
out vec4 v_colour;
out float v_scalar;

void main() {
  v_normal = mat3(u_model) * a_normal;
  v_colour = a_colour;
  v_scalar = a_scalar;
  gl_Position = u_view_projection * u_model * vec4(a_position, 1.0);
}
