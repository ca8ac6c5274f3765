// Frames through ffmpeg: count, orientation (OpenGL rows bottom to top) and colours survive;
// a missing ffmpeg or one that gave up is reported instead of killing the process.
#include "viz/ffmpeg_pipe.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "viz/tool_test_support.hpp"

namespace cerebellum {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 32;

// rgb rows bottom to top: the lower half red, the upper half blue
std::vector<std::uint8_t> two_band_frame() {
  std::vector<std::uint8_t> rgb(3 * kWidth * kHeight);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      std::uint8_t* p = &rgb[3 * (row * kWidth + col)];
      const bool lower = row < kHeight / 2;
      p[0] = lower ? 255 : 0;
      p[2] = lower ? 0 : 255;
    }
  }
  return rgb;
}

// rgb24 of the decoded frame, rows top to bottom as image files store them
std::vector<std::uint8_t> decode_rgb(const std::string& media, const test::ScratchDir& dir) {
  const std::string raw = dir / "decoded.rgb";
  const auto result = test::run_command("ffmpeg -v error -y -i " + test::quoted(media) +
                                        " -frames:v 1 -f rawvideo -pix_fmt rgb24 " + test::quoted(raw));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const std::string bytes = test::read_file(raw);
  return {bytes.begin(), bytes.end()};
}

TEST(FfmpegPipe, VideoKeepsFrameCountOrientationAndColours) {
  test::ScratchDir dir;
  const std::string path = dir / "bands.mp4";
  const auto frame = two_band_frame();
  {
    FfmpegPipe pipe(path, kWidth, kHeight, 10.0);
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(pipe.write_frame(frame.data()));
    EXPECT_EQ(pipe.frames_written(), 3u);
    ASSERT_TRUE(pipe.finish());
  }
  const auto probe = test::run_command(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames,width,height -of csv=p=0 " +
      test::quoted(path));
  EXPECT_EQ(probe.output, "64,32,3\n");
  const auto rgb = decode_rgb(path, dir);
  ASSERT_EQ(rgb.size(), 3u * kWidth * kHeight);
  // the top of the picture is the last rows OpenGL gave: blue; the bottom is red (lossy codec)
  const std::uint8_t* top = &rgb[3 * (2 * kWidth + 5)];
  const std::uint8_t* bottom = &rgb[3 * ((kHeight - 3) * kWidth + 5)];
  EXPECT_LT(top[0], 60);
  EXPECT_GT(top[2], 190);
  EXPECT_GT(bottom[0], 190);
  EXPECT_LT(bottom[2], 60);
}

TEST(FfmpegPipe, PngKeepsOneFrameExactly) {
  test::ScratchDir dir;
  const std::string path = dir / "shot.png";
  std::vector<std::uint8_t> frame(3 * kWidth * kHeight);
  for (std::size_t i = 0; i < frame.size(); ++i) frame[i] = static_cast<std::uint8_t>((i * 7) % 251);
  FfmpegPipe pipe(path, kWidth, kHeight, 1.0);
  ASSERT_TRUE(pipe.write_frame(frame.data()));
  ASSERT_TRUE(pipe.finish());
  const auto rgb = decode_rgb(path, dir);
  ASSERT_EQ(rgb.size(), frame.size());
  const std::size_t row_bytes = 3 * kWidth;
  for (int row = 0; row < kHeight; ++row) {
    for (std::size_t b = 0; b < row_bytes; ++b) {
      ASSERT_EQ(rgb[row * row_bytes + b], frame[(kHeight - 1 - row) * row_bytes + b]) << "row " << row;
    }
  }
}

TEST(FfmpegPipe, AnFfmpegThatGaveUpIsAnErrorNotASignal) {
  const auto frame = two_band_frame();
  FfmpegPipe pipe("/nonexistent-directory/cerebellum/out.mp4", kWidth, kHeight, 10.0);
  bool refused = false;
  for (int i = 0; i < 1000 && !refused; ++i) refused = !pipe.write_frame(frame.data());
  EXPECT_TRUE(refused);
  EXPECT_FALSE(pipe.finish());
}

TEST(FfmpegPipe, MissingFfmpegIsNamedWithItsPackage) {
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent-directory", 1);
  std::string message;
  try {
    FfmpegPipe pipe("/tmp/never.mp4", kWidth, kHeight, 10.0);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(message, "ffmpeg not found on PATH (Debian package: ffmpeg)");
}

}  // namespace
}  // namespace cerebellum
