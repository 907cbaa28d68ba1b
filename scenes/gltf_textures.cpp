// Base colour textures: images captured encoded while tinygltf parses, their size read from the
// image header (stb_image's info call: a few bytes, no pixels) and checked against the texture
// budget *before* anything is decoded, one decode per (image, sampler), decoding in parallel.
// A 16384^2 PNG of a few KB would otherwise allocate 1 GiB before anyone could say no; a small
// header over a zlib bomb is bounded inside the decoder (scenes/image_decode.cpp).
#include "scenes/gltf_internal.h"
#include "scenes/image_decode.h"

#include <algorithm>
#include <atomic>
#include <thread>

namespace shadowlab::gltf {
namespace {

std::string imageLabel(const tinygltf::Model& m, int image) {
    const tinygltf::Image& src = m.images[std::size_t(image)];
    const std::string& name = src.uri.empty() || src.uri.rfind("data:", 0) == 0 ? src.name : src.uri;
    std::string text = "image " + std::to_string(image);
    if (!name.empty()) text.append(" ").append(quoted(name));
    return text;
}

// Decodes to RGBA8; checks the result against the size the header promised, which the budget was
// charged for.
bool decodeRgba8(const std::vector<std::uint8_t>& bytes, Texture& texture, std::string& reason) {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba8;
    if (!decoder::decodeRgba8(bytes, width, height, rgba8, reason)) return false;
    if (width != texture.width || height != texture.height) {
        reason = "decoded to " + std::to_string(width) + "x" + std::to_string(height) + ", its header says " +
                 std::to_string(texture.width) + "x" + std::to_string(texture.height);
        return false;
    }
    texture.rgba8 = std::move(rgba8);
    return true;
}

// An image index from a texture's "source" or an extension's "source"; -1 when absent or invalid.
int sourceIndex(const json* holder) {
    const json* source = holder ? member(*holder, "source") : nullptr;
    return source && source->is_number_unsigned() && source->get<std::uint64_t>() < (1u << 30) ? source->get<int>() : -1;
}

}  // namespace

TextureSource textureSource(const json& texture) {
    const json* extensions = member(texture, "extensions");
    TextureSource chosen;
    chosen.basisuSkipped = extensions && member(*extensions, "KHR_texture_basisu");
    // EXT_texture_webp's image is decoded (libwebp); the core source is its fallback.
    if (const int webp = extensions ? sourceIndex(member(*extensions, "EXT_texture_webp")) : -1; webp >= 0)
        chosen.image = webp;
    else
        chosen.image = sourceIndex(&texture);
    return chosen;
}

std::vector<char> baseColorImages(const json& root) {
    const json* images = member(root, "images");
    const json* textures = member(root, "textures");
    const json* materials = member(root, "materials");
    std::vector<char> wanted(images && images->is_array() ? images->size() : 0, 0);
    if (!textures || !textures->is_array() || !materials || !materials->is_array()) return wanted;
    for (const json& material : *materials) {
        const json* pbr = member(material, "pbrMetallicRoughness");
        const json* info = pbr ? member(*pbr, "baseColorTexture") : nullptr;
        const json* index = info ? member(*info, "index") : nullptr;
        if (!index || !index->is_number_unsigned() || index->get<std::uint64_t>() >= textures->size()) continue;
        const int image = textureSource((*textures)[index->get<std::size_t>()]).image;
        if (image >= 0 && std::size_t(image) < wanted.size()) wanted[std::size_t(image)] = 1;
    }
    return wanted;
}

bool captureImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto* capture = static_cast<ImageCapture*>(user);
    if (image->bufferView >= 0) {
        // tinygltf takes a pointer into the buffer without checking the view's range.
        const tinygltf::Model& m = *capture->model;
        const auto view = std::size_t(image->bufferView);
        const bool valid = view < m.bufferViews.size() && m.bufferViews[view].buffer >= 0 &&
                           std::size_t(m.bufferViews[view].buffer) < m.buffers.size() &&
                           m.bufferViews[view].byteOffset <= m.buffers[std::size_t(m.bufferViews[view].buffer)].data.size() &&
                           m.bufferViews[view].byteLength <=
                               m.buffers[std::size_t(m.bufferViews[view].buffer)].data.size() - m.bufferViews[view].byteOffset;
        if (!valid) {
            if (err)
                *err += "image " + std::to_string(index) + ": bufferView " + std::to_string(image->bufferView) +
                        " is out of bounds of its buffer";
            return false;
        }
    }
    if (bytes == nullptr || size <= 0) {
        if (err) *err += "image " + std::to_string(index) + " is empty";
        return false;
    }
    if (std::size_t(index) >= capture->wanted.size() || !capture->wanted[std::size_t(index)]) return true;
    capture->encoded[index] = std::make_shared<const std::vector<std::uint8_t>>(bytes, bytes + size);
    return true;
}

// Reads the header only; false (with a warning: the material falls back to its factor) when the
// image alone or the running total is over the texture budget. An unreadable header is an error.
bool Converter::imageFitsBudget(int image, int& width, int& height) {
    std::string reason;
    if (!decoder::readSize(*images.encoded.at(image), width, height, reason))
        fail(imageLabel(m, image) + " cannot be decoded (" + reason + ")");
    if (width <= 0 || height <= 0) fail(imageLabel(m, image) + " has no pixels (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    const LoadLimits& limits = options.limits;
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (pixels > limits.texturePixels) {
        warn(imageLabel(m, image) + " (" + size + ") " + overLimit("texturePixels", limits.texturePixels) +
             ": not decoded, its materials use their base colour factor");
        return false;
    }
    if (textureBytes + pixels * 4 > limits.textureBytes) {
        warn(imageLabel(m, image) + " (" + size + ", " + std::to_string(pixels * 4) + " bytes decoded) with the " +
             std::to_string(textureBytes) + " bytes of textures before it " + overLimit("textureBytes", limits.textureBytes) +
             ": not decoded, its materials use their base colour factor");
        return false;
    }
    textureBytes += pixels * 4;
    return true;
}

int Converter::useTexture(int gltfTexture, const std::string& what) {
    if (gltfTexture < 0 || std::size_t(gltfTexture) >= m.textures.size())
        fail(what + ": texture " + std::to_string(gltfTexture) + " does not exist");
    if (auto it = textureSlots.find(gltfTexture); it != textureSlots.end()) return it->second;
    const tinygltf::Texture& t = m.textures[std::size_t(gltfTexture)];
    const std::string where = label("texture", std::size_t(gltfTexture), t.name);
    const json* texturesJson = member(root, "textures");
    const TextureSource chosen = texturesJson && texturesJson->is_array() && std::size_t(gltfTexture) < texturesJson->size()
                                     ? textureSource((*texturesJson)[std::size_t(gltfTexture)])
                                     : TextureSource{};
    const int source = chosen.image;
    if (source < 0) {
        if (chosen.basisuSkipped)
            warn(where + " is a KTX2 / Basis Universal image only (KHR_texture_basisu), and this build has no Basis "
                         "Universal decoder: " + what + " uses its base colour factor");
        else
            warn(where + " has no PNG, JPEG or WebP source; drawn untextured");
        return textureSlots[gltfTexture] = -1;
    }
    if (chosen.basisuSkipped)
        warn(where + ": its KTX2 / Basis Universal image is not decoded (no Basis Universal decoder in this build), "
                     "its PNG/JPEG/WebP source is used instead");
    if (std::size_t(source) >= m.images.size()) fail(where + ": image " + std::to_string(source) + " does not exist");
    if (t.sampler >= 0 && std::size_t(t.sampler) >= m.samplers.size())
        fail(where + ": sampler " + std::to_string(t.sampler) + " does not exist");
    if (!images.encoded.count(source))
        fail(imageLabel(m, source) + " could not be read (missing or unreadable file)");
    // Textures that differ only by name share one decoded copy.
    const TextureKey key{source, t.sampler};
    if (auto it = sharedSlots.find(key); it != sharedSlots.end()) return textureSlots[gltfTexture] = it->second;

    Texture texture;
    if (!imageFitsBudget(source, texture.width, texture.height))
        return textureSlots[gltfTexture] = sharedSlots[key] = -1;
    const tinygltf::Image& image = m.images[std::size_t(source)];
    texture.name = !t.name.empty() ? t.name : !image.name.empty() ? image.name : image.uri;
    if (t.sampler >= 0) {
        const tinygltf::Sampler& s = m.samplers[std::size_t(t.sampler)];
        if (s.magFilter >= 0) texture.sampler.magFilter = s.magFilter;
        if (s.minFilter >= 0) texture.sampler.minFilter = s.minFilter;
        texture.sampler.wrapS = s.wrapS;
        texture.sampler.wrapT = s.wrapT;
    }
    if (options.textures == TextureDecoding::Deferred) texture.encoded = images.encoded.at(source);
    const int slot = int(scene.textures.size());
    scene.textures.push_back(std::move(texture));
    slotImages.push_back(source);
    return textureSlots[gltfTexture] = sharedSlots[key] = slot;
}

void Converter::decodeTextures() {
    if (options.textures != TextureDecoding::Decode || slotImages.empty()) return;
    const std::size_t jobs = slotImages.size();
    const std::size_t threads = std::min<std::size_t>(jobs, std::max(1u, std::min(8u, std::thread::hardware_concurrency())));
    std::vector<std::string> errors(jobs);
    std::atomic<std::size_t> next{0}, decoded{0};
    // Only this (the loading) thread reports, after each of its own images: the callback is never
    // called concurrently.
    auto report = [&] {
        reportProgress(options, kLoadProgress.meshes + (kLoadProgress.textures - kLoadProgress.meshes) *
                                                           double(decoded.load()) / double(jobs));
    };
    const std::thread::id loadingThread = std::this_thread::get_id();
    auto work = [&] {
        for (std::size_t i = next++; i < jobs; i = next++) {
            std::string reason;
            try {
                if (!decodeRgba8(*images.encoded.at(slotImages[i]), scene.textures[i], reason))
                    errors[i] = imageLabel(m, slotImages[i]) + " cannot be decoded (" + reason + ")";
            } catch (const std::exception& e) {
                errors[i] = imageLabel(m, slotImages[i]) + ": " + e.what();
            }
            ++decoded;
            if (std::this_thread::get_id() == loadingThread) report();
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    report();
    for (const std::string& e : errors)
        if (!e.empty()) fail(e);
}

}  // namespace shadowlab::gltf

namespace shadowlab {

bool decodeTexture(Texture& texture, std::string& error) {
    if (!texture.encoded) {
        error = "texture '" + texture.name + "' has no encoded image to decode (already decoded, or loaded without it)";
        return false;
    }
    std::string reason;
    if (!gltf::decodeRgba8(*texture.encoded, texture, reason)) {
        error = "texture '" + texture.name + "' cannot be decoded (" + reason + ")";
        return false;
    }
    texture.encoded.reset();
    return true;
}

}  // namespace shadowlab
