#include "io/common/link_faults.hpp"

#include <cmath>
#include "core/number_text.hpp"

namespace cerebellum {
namespace {

constexpr std::size_t kDelayedMax = 4096;
constexpr double kDelayMaxS = 10.0;

std::string format_number(double value) { return number_text(value, 12); }

}  // namespace

std::string link_names(const std::string& separator) {
  std::string names;
  for (const char* name : kLinkNames) names += (names.empty() ? "" : separator) + name;
  return names;
}

LinkFaultParse parse_link_fault(const std::vector<std::string>& words) {
  const auto failure = [](std::string why) { return LinkFaultParse{std::nullopt, std::move(why)}; };
  const std::string usage = "link " + link_names("|") + " drop P | delay SECONDS | duplicate P | corrupt P | clear";
  if (words.size() < 3 || words[0] != "link") return failure("expected: " + usage);
  LinkFaultRequest request;
  bool known = false;
  for (std::size_t i = 0; i < kLinkNames.size(); ++i) {
    if (words[1] == kLinkNames[i]) {
      request.link = static_cast<Link>(i);
      known = true;
    }
  }
  if (!known) return failure("unknown link '" + words[1].substr(0, 32) + "' (accepted: " + link_names(", ") + ")");
  request.field = words[2];
  if (request.field == "clear") {
    if (words.size() != 3) return failure("link " + words[1] + " clear takes nothing more");
    return LinkFaultParse{request, ""};
  }
  const bool probability = request.field == "drop" || request.field == "duplicate" || request.field == "corrupt";
  if (!probability && request.field != "delay") {
    return failure("unknown link fault '" + request.field.substr(0, 32) +
                   "' (accepted: drop, delay, duplicate, corrupt, clear)");
  }
  if (words.size() != 4) return failure("link " + words[1] + " " + request.field + " takes one value");
  const double upper = probability ? 1.0 : kDelayMaxS;
  const std::optional<double> value = finite_number(words[3]);
  if (!value || *value < 0.0 || *value > upper) {
    return failure("link " + request.field + " must be a number in [0, " + format_number(upper) + "], got '" +
                   words[3].substr(0, 32) + "'");
  }
  request.value = *value;
  return LinkFaultParse{request, ""};
}

std::string link_fault_text(const LinkFaultRequest& request) {
  std::string text = "link ";
  text += kLinkNames[static_cast<std::size_t>(request.link)];
  text += ' ';
  text += request.field;
  if (request.field != "clear") {
    text += ' ';
    text += format_number(request.value);
  }
  return text;
}

LinkFaults::LinkFaults(unsigned seed) : rng_(seed) {}

void LinkFaults::apply(const LinkFaultRequest& request) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (request.field == "clear") settings_ = LinkFaultSettings{};
  if (request.field == "drop") settings_.drop = request.value;
  if (request.field == "duplicate") settings_.duplicate = request.value;
  if (request.field == "corrupt") settings_.corrupt = request.value;
  if (request.field == "delay") settings_.delay_s = request.value;
}

LinkFaultSettings LinkFaults::settings() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return settings_;
}

LinkFaultCounters LinkFaults::counters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void LinkFaults::deliver_now(std::vector<std::uint8_t>& bytes, const LinkFaultSettings& settings,
                             const Deliver& deliver) {
  std::uniform_real_distribution<double> chance(0.0, 1.0);
  bool corrupt = false, twice = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    corrupt = !bytes.empty() && chance(rng_) < settings.corrupt;
    twice = chance(rng_) < settings.duplicate;
    if (corrupt) {
      std::uniform_int_distribution<std::size_t> where(0, bytes.size() - 1);
      std::uniform_int_distribution<int> flip(1, 255);
      bytes[where(rng_)] ^= static_cast<std::uint8_t>(flip(rng_));
      ++counters_.corrupted;
    }
    if (twice) ++counters_.duplicated;
  }
  deliver(bytes.data(), bytes.size());
  if (twice) deliver(bytes.data(), bytes.size());
}

void LinkFaults::pass(const std::uint8_t* data, std::size_t size, double now_s, const Deliver& deliver) {
  LinkFaultSettings settings;
  bool drop = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    settings = settings_;
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    drop = settings.drop > 0.0 && chance(rng_) < settings.drop;
    if (drop) ++counters_.dropped;
    if (!drop && settings.delay_s > 0.0) {
      if (delayed_.size() >= kDelayedMax) {
        ++counters_.overflowed;
      } else {
        delayed_.push_back({now_s + settings.delay_s, std::vector<std::uint8_t>(data, data + size)});
        ++counters_.delayed;
      }
      return;
    }
  }
  if (drop) return;
  // the common case without faults: straight through, no copy
  if (settings.corrupt <= 0.0 && settings.duplicate <= 0.0) {
    deliver(data, size);
    return;
  }
  std::vector<std::uint8_t> bytes(data, data + size);
  deliver_now(bytes, settings, deliver);
}

void receive_through(LinkFaults* faults, const std::uint8_t* data, std::size_t size, double now_s,
                     const LinkFaults::Deliver& deliver) {
  if (faults == nullptr) {
    deliver(data, size);
  } else {
    faults->pass(data, size, now_s, deliver);
  }
}

void release_due(LinkFaults* faults, double now_s, const LinkFaults::Deliver& deliver) {
  if (faults != nullptr) faults->release(now_s, deliver);
}

void LinkFaults::release(double now_s, const Deliver& deliver) {
  for (;;) {
    Delayed due;
    LinkFaultSettings settings;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (delayed_.empty() || delayed_.front().due_s > now_s) return;
      due = std::move(delayed_.front());
      delayed_.pop_front();
      settings = settings_;
    }
    deliver_now(due.bytes, settings, deliver);
  }
}

}  // namespace cerebellum
