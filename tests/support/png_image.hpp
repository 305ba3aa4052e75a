#pragma once
// A PNG read back for checks: its size and RGB pixels, and how many colours it holds.

#include <doctest/doctest.h>
#include <stb_image.h>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace impulse::test {

struct PngImage {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;  // top row first

    // The pixel as 0xRRGGBB.
    unsigned at(int x, int y) const {
        const std::size_t i =
            (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
        return static_cast<unsigned>(rgb[i] << 16 | rgb[i + 1] << 8 | rgb[i + 2]);
    }
};

inline PngImage png_from_bytes(const std::string& bytes) {
    PngImage image;
    int channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()),
                              &image.width, &image.height, &channels, 3),
        stbi_image_free);
    REQUIRE_MESSAGE(data != nullptr, "not a PNG");
    image.rgb.assign(data.get(), data.get() + static_cast<std::size_t>(image.width * image.height * 3));
    return image;
}

inline PngImage load_png(const std::filesystem::path& path) {
    PngImage image;
    int channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load(path.string().c_str(), &image.width, &image.height, &channels, 3), stbi_image_free);
    REQUIRE_MESSAGE(data != nullptr, "not a PNG: " << path);
    image.rgb.assign(data.get(), data.get() + static_cast<std::size_t>(image.width * image.height * 3));
    return image;
}

inline std::size_t distinct_colours(const PngImage& image) {
    std::set<unsigned> colours;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
        colours.insert(image.rgb[i] << 16 | image.rgb[i + 1] << 8 | image.rgb[i + 2]);
    return colours.size();
}

}  // namespace impulse::test
