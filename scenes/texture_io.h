// Textures: image files, procedural images, and GL-style mip chains.
//
// Every image is 8-bit RGBA with row 0 at the top of the picture (as stored in PNG/JPEG/TGA),
// which is GL's t = 0 row when the image is uploaded top row first, as OBJ/glTF textures are.
#pragma once

#include <string>
#include <vector>

#include "scenes/mesh.h"
#include "scenes/texture.h"

namespace rastrace {

// PNG, JPEG, TGA (and anything else OpenImageIO reads), converted to 8-bit RGBA: grey becomes
// (g, g, g, 255), RGB gets alpha 255. InputError if missing or unreadable.
Image load_image(const std::string& path);
// The same from an image file held in memory (textures embedded in glTF/GLB); `name` (with the
// file's extension, e.g. "truck.glb#*0.png") picks the decoder and names it in errors.
Image load_image_from_memory(const std::vector<std::uint8_t>& bytes, const std::string& name);

// size x size, checks x checks squares, alternating white (255) and dark grey (64), the top-left
// square white. size >= 1, 1 <= checks <= size.
Image make_checker(int size, int checks);

// Yang et al.'s four-colour map: four quadrants of distinct colours. Top-left red, top-right
// green, bottom-left blue, bottom-right yellow (u < 0.5 is left, v < 0.5 is the top row half).
Image make_four_colour(int size);

// R = u (x / (size-1) * 255), G = v (y / (size-1) * 255), B = 0: every texel a different colour
// for size <= 256, useful to see which texels a renderer fetched.
Image make_uv_gradient(int size);

// GL-style mip chain: levels[0] = base, each next level max(1, floor(w/2)) x max(1, floor(h/2))
// down to 1x1 (1 + floor(log2(max(w, h))) levels). Box filter: a destination texel is the exact
// area average of the source rectangle it covers. For even sizes that is the plain 2x2 average;
// for an odd size 2n+1 -> n each destination texel covers (2n+1)/n source texels, so the source
// texel straddling a boundary is split between its two neighbours by its overlap (e.g. 5 -> 2:
// weights 1, 1, 0.5 | 0.5, 1, 1, over 2.5). Channels are averaged independently and rounded to
// nearest.
std::vector<Image> build_mip_chain(Image base);

// The image a TextureSource describes (file or procedural) with its full mip chain, compressed
// to source.format (compress_texture). Kind::None is an error (there is nothing to load).
Texture load_texture(const TextureSource& source);

// Stores an RGBA8 texture as `format`: each mip level (built from the RGBA8 base, as a GPU
// texture's levels are) is encoded on its own, its blocks kept in Texture::blocks, and its texels
// replaced by the decoded ones, which the sampler then reads. Rgba8 leaves the texture as it is.
Texture compress_texture(Texture texture, TextureFormat format);

}  // namespace rastrace
