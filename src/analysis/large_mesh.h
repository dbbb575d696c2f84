// A large OBJ for the bench and the tests ("a 1-million-triangle OBJ loads and renders
// at 512x512"): an n x n grid of quads, gently displaced, with uvs and no normals (the loader
// computes them), written as text the way exporters write OBJ, and a scene that shows it.
#pragma once
#include <string>

namespace dsr {

// Writes FILE.obj with (n + 1)^2 shared corners and n^2 quads (2 n^2 triangles after
// triangulation); throws dsr::Error naming the file if it cannot be written.
void write_grid_obj(const std::string& path, int n);

// Writes DIR/grid_<n>.obj (unless it exists with the expected size of n) and
// DIR/grid_<n>.scene (one material, one light, the camera above the grid); returns the scene's
// path. The bench's "large mesh" scene: make bench writes it under build/.
std::string write_grid_scene(const std::string& dir, int n);

}  // namespace dsr
