#include "preview_board.h"

#include <algorithm>
#include <vector>

namespace lucent::preview {

void PreviewBoard::publishImage(std::string json) {
  {
    std::lock_guard lock(mutex_);
    image_ = Entry{++seq_, "image", std::move(json)};
    tiles_.clear();
  }
  wake_.notify_all();
}

void PreviewBoard::publishTile(const std::string& key, std::string json) {
  {
    std::lock_guard lock(mutex_);
    tiles_[key] = Entry{++seq_, "tile", std::move(json)};
  }
  wake_.notify_all();
}

void PreviewBoard::publishStatus(std::string json) {
  {
    std::lock_guard lock(mutex_);
    status_ = Entry{++seq_, "status", std::move(json)};
  }
  wake_.notify_all();
}

void PreviewBoard::publishComparison(std::string json) {
  {
    std::lock_guard lock(mutex_);
    comparison_ = Entry{++seq_, "comparison", std::move(json)};
  }
  wake_.notify_all();
}

bool PreviewBoard::collect(uint64_t& cursor, std::chrono::milliseconds wait, std::string& out) {
  out.clear();
  std::unique_lock lock(mutex_);
  wake_.wait_for(lock, wait, [&] { return closed_ || seq_ > cursor; });
  if (closed_) return false;
  std::vector<const Entry*> newer;
  auto take = [&](const Entry& e) {
    if (e.seq > cursor) newer.push_back(&e);
  };
  if (image_) take(*image_);
  if (status_) take(*status_);
  if (comparison_) take(*comparison_);
  for (const auto& entry : tiles_) take(entry.second);
  std::sort(newer.begin(), newer.end(),
            [](const Entry* a, const Entry* b) { return a->seq < b->seq; });
  for (const Entry* e : newer) {
    // The data is one line (JSON without line breaks), as an event's data field must be.
    out += "event: " + e->event + "\ndata: " + e->data + "\n\n";
    cursor = e->seq;
  }
  return true;
}

void PreviewBoard::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  wake_.notify_all();
}

size_t PreviewBoard::bytesHeld() const {
  std::lock_guard lock(mutex_);
  size_t n = 0;
  if (image_) n += image_->data.size();
  if (status_) n += status_->data.size();
  if (comparison_) n += comparison_->data.size();
  for (const auto& entry : tiles_) n += entry.second.data.size();
  return n;
}

}  // namespace lucent::preview
