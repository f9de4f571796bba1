// animate OUT.webp FPS QUALITY FRAME.png...   |   animate --verify FILE.webp
// The READMEs' animations: frames a step wrote with --record, encoded as one animated WebP through
// libwebp's WebPAnimEncoder (lossy, QUALITY 0..100; full colour, unlike GIF's 256, and a fraction
// of the size). --verify decodes a file with WebPAnimDecoder and prints its frame count, size and
// bytes; both exit non-zero with one line on stderr on any failure.
#include "common/file_output.hpp"
#include "common/image.hpp"

#include <webp/demux.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "animate: %s\n", message.c_str());
    return 1;
}

std::vector<std::uint8_t> read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int verify(const std::string& path) {
    const std::vector<std::uint8_t> bytes = read_file(path);
    if (bytes.empty()) return fail("'" + path + "' is missing or empty");
    WebPData data{bytes.data(), bytes.size()};
    WebPAnimDecoderOptions options;
    WebPAnimDecoderOptionsInit(&options);
    WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
    if (decoder == nullptr) return fail("'" + path + "' is not an animated WebP");
    WebPAnimInfo info;
    WebPAnimDecoderGetInfo(decoder, &info);
    int frames = 0, last_ms = 0;
    std::uint8_t* pixels = nullptr;
    while (WebPAnimDecoderHasMoreFrames(decoder) && WebPAnimDecoderGetNext(decoder, &pixels, &last_ms)) ++frames;
    WebPAnimDecoderDelete(decoder);
    if (frames != int(info.frame_count)) return fail("'" + path + "': only " + std::to_string(frames) + " frames decode");
    std::printf("%s: %d frames, %ux%u, %d ms, %zu bytes\n", path.c_str(), frames, info.canvas_width,
                info.canvas_height, last_ms, bytes.size());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--verify") return verify(argv[2]);
    if (argc < 5) return fail("usage: animate OUT.webp FPS QUALITY FRAME.png... | animate --verify FILE.webp");
    const std::string out = argv[1];
    const double fps = std::atof(argv[2]), quality = std::atof(argv[3]);
    if (!(fps > 0 && fps <= 60)) return fail("FPS must be in (0, 60], got '" + std::string(argv[2]) + "'");
    if (!(quality >= 0 && quality <= 100)) return fail("QUALITY must be in [0, 100], got '" + std::string(argv[3]) + "'");

    WebPAnimEncoder* encoder = nullptr;
    WebPConfig config;
    if (!WebPConfigInit(&config)) return fail("libwebp: version mismatch");
    config.quality = float(quality);
    config.method = 6;  // slowest, smallest
    int width = 0, height = 0, timestamp_ms = 0;
    std::string error;
    for (int i = 4; i < argc && error.empty(); ++i) {
        const auto image = ocean::load_image(argv[i], &error);
        if (!image) break;
        if (encoder == nullptr) {
            width = image->width;
            height = image->height;
            WebPAnimEncoderOptions options;
            WebPAnimEncoderOptionsInit(&options);
            options.anim_params.loop_count = 0;  // for ever
            encoder = WebPAnimEncoderNew(width, height, &options);
            if (encoder == nullptr) return fail("libwebp cannot encode " + std::to_string(width) + "x" + std::to_string(height));
        } else if (image->width != width || image->height != height) {
            error = std::string("'") + argv[i] + "' is not " + std::to_string(width) + "x" + std::to_string(height);
            break;
        }
        WebPPicture picture;
        WebPPictureInit(&picture);
        picture.width = width;
        picture.height = height;
        picture.use_argb = 1;
        if (!WebPPictureImportRGBA(&picture, image->rgba.data(), width * 4) ||
            !WebPAnimEncoderAdd(encoder, &picture, timestamp_ms, &config))
            error = std::string("libwebp cannot add '") + argv[i] + "'";
        WebPPictureFree(&picture);
        timestamp_ms = int(double(i - 3) * 1000.0 / fps + 0.5);
    }
    WebPData data;
    WebPDataInit(&data);
    if (error.empty() && (!WebPAnimEncoderAdd(encoder, nullptr, timestamp_ms, nullptr) ||
                          !WebPAnimEncoderAssemble(encoder, &data)))
        error = "libwebp cannot assemble the animation";
    WebPAnimEncoderDelete(encoder);
    if (error.empty())  // whole or not at all: a WebP cut short by a full disk never takes the name
        if (auto failure = ocean::write_file(out, {reinterpret_cast<const char*>(data.bytes), data.size}))
            error = *failure;
    WebPDataClear(&data);
    if (!error.empty()) return fail(error);
    return verify(out);
}
