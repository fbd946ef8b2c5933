// TexturePrefetcher: see texture_prefetch.h.
#include "texture_prefetch.h"

#include <algorithm>

namespace lfd::bake {

TexturePrefetcher::TexturePrefetcher(std::function<Texture(uint32_t)> bake, std::vector<uint64_t> bytes,
                                     ThreadBudget& threads, uint64_t memoryLimit)
    : bake_(std::move(bake)), bytes_(std::move(bytes)), threads_(threads), memoryLimit_(memoryLimit),
      slots_(bytes_.size())
{
}

TexturePrefetcher::~TexturePrefetcher()
{
    for (std::thread& helper : helpers_)
        helper.join();
}

uint64_t TexturePrefetcher::peakHeldBytes() const
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return peakHeld_;
}

void TexturePrefetcher::hold(uint64_t bytes)
{
    held_ += bytes;
    peakHeld_ = std::max(peakHeld_, held_);
}

void TexturePrefetcher::startAhead(uint32_t index)
{
    for (uint32_t j = std::max(nextToStart_, index + 1); j < slots_.size(); ++j) {
        // In order only, so memory goes to the textures the writer needs first.
        if (j != nextToStart_ || held_ + bytes_[j] > memoryLimit_ || threads_.take(1) == 0)
            return;
        slots_[j].started = true;
        ++nextToStart_;
        hold(bytes_[j]);
        try {
            helpers_.emplace_back([this, j] {
                Slot result;
                try {
                    result.texture = bake_(j);
                } catch (...) {
                    result.error = std::current_exception();
                }
                threads_.give(1); // before anyone waiting on this texture wakes up
                const std::lock_guard<std::mutex> lock(mutex_);
                slots_[j].texture = std::move(result.texture);
                slots_[j].error = result.error;
                done_.notify_all();
            });
        } catch (...) {
            // note: no thread: the texture goes back to being baked by take().
            threads_.give(1);
            slots_[j].started = false;
            --nextToStart_;
            held_ -= bytes_[j];
            return;
        }
    }
}

Texture TexturePrefetcher::take(uint32_t index)
{
    std::unique_lock<std::mutex> lock(mutex_);
    // The caller has dropped the texture it took last.
    if (lastTaken_)
        held_ -= bytes_[*lastTaken_];
    lastTaken_ = index;

    Slot& slot = slots_.at(index);
    if (!slot.started) {
        // Nobody has it: bake it here (a texture over the memory limit lands here, with
        // the threads the budget has left for its mip chain).
        slot.started = true;
        nextToStart_ = std::max(nextToStart_, index + 1);
        hold(bytes_[index]);
        startAhead(index);
        lock.unlock();
        return bake_(index);
    }
    startAhead(index);
    done_.wait(lock, [&] { return slot.texture.has_value() || slot.error; });
    if (slot.error)
        std::rethrow_exception(slot.error);
    Texture texture = std::move(*slot.texture);
    slot.texture.reset();
    startAhead(index); // memory may have been waiting on this one
    return texture;
}

} // namespace lfd::bake
