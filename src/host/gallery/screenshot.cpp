#include "host/gallery/screenshot.h"

#include <fmt/format.h>

#include <ctime>
#include <utility>

#include "image/image_io.h"

namespace vitrine::host {
namespace {

std::string stemFor(std::string_view scene) {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  return fmt::format("vitrine-{}-{}", scene, stamp);
}

}  // namespace

Screenshots::Screenshots(const gpu::Device& device, uint32_t framesInFlight, std::filesystem::path folder)
    : device_(device), folder_(std::move(folder)), pending_(framesInFlight) {}

ImageNotes Screenshots::notes(std::string_view scene, VkExtent2D shown, VkExtent2D rendered) {
  return {{"vitrine:scene", std::string(scene)},
          {"vitrine:window_size", fmt::format("{}x{}", shown.width, shown.height)},
          {"vitrine:render_size", fmt::format("{}x{}", rendered.width, rendered.height)}};
}

void Screenshots::record(VkCommandBuffer cmd, uint32_t slot, gpu::Image& target, VkExtent2D rendered,
                         std::string_view scene, gpu::PassTimer* timer) {
  if (!requested_) return;
  requested_ = false;
  const VkExtent2D extent = target.extent2d();
  gpu::Pass pass(device_, timer, cmd, "screenshot copy");
  Pending shot{gpu::Buffer(device_, VkDeviceSize(extent.width) * extent.height * 4 * sizeof(uint16_t),
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "screenshot readback"),
               extent, rendered, std::string(scene), stemFor(scene)};
  gpu::recordReadback(cmd, target, shot.pixels);
  pending_[slot] = std::move(shot);
}

std::optional<std::string> Screenshots::collect(uint32_t slot) {
  if (!pending_[slot]) return std::nullopt;
  const Pending shot = std::move(*pending_[slot]);
  pending_[slot].reset();
  try {
    return write(shot);
  } catch (const std::exception& e) {  // a full disk should not end the session
    return fmt::format("screenshot failed: {}", e.what());
  }
}

std::string Screenshots::write(const Pending& shot) const {
  shot.pixels.invalidate();
  const ImageRgba image = imageFromHalves(shot.extent.width, shot.extent.height, shot.pixels.view<const uint16_t>());
  std::filesystem::create_directories(folder_);
  // The absolute path: the console line must say where the files are, whatever the working folder.
  const std::filesystem::path folder = std::filesystem::absolute(folder_);
  // Two screenshots within a second would share a name; the later one gets a number instead.
  std::filesystem::path base = folder / shot.stem;
  for (int n = 2; std::filesystem::exists(base.string() + ".exr"); ++n)
    base = folder / fmt::format("{}-{}", shot.stem, n);
  const ImageNotes about = notes(shot.scene, shot.extent, shot.rendered);
  const std::string size = fmt::format("{}x{}, rendered at {}x{}", shot.extent.width, shot.extent.height,
                                       shot.rendered.width, shot.rendered.height);
  writeImage(base.string() + ".exr", image, about);
  writeImage(base.string() + ".png", image, about);
  return fmt::format("saved {}.{{exr,png}} ({})", base.string(), size);
}

}  // namespace vitrine::host
