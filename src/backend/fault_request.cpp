#include "backend/fault_request.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/joint_layout.hpp"
#include "core/motor_health.hpp"
#include "core/number_text.hpp"

namespace cerebellum {
namespace {

struct KindWord {
  FaultTarget target;
  FaultKind kind;
  const char* word;
  bool takes_value;
  double lower, upper;  // the value's range (inclusive)
  double fallback;      // value when optional and absent (NaN: required)
  bool whole = false;   // the value is a whole number
  // the value is one of these letters, kept as its index (the phase of an over-current)
  const char* letters = nullptr;
};

constexpr double kRequired = std::numeric_limits<double>::quiet_NaN();

// one home for every fault's word, value and range
const std::array<KindWord, 20> kKinds{{
    {FaultTarget::Motor, FaultKind::Disconnected, "disconnected", false, 0, 0, 0},
    {FaultTarget::Motor, FaultKind::OverTemperature, "over_temperature", false, 0, 0, 0},
    {FaultTarget::Motor, FaultKind::DriverFault, "driver_fault", false, 0, 0, 0},
    {FaultTarget::Motor, FaultKind::UnderVoltage, "under_voltage", false, 0, 0, 0},
    {FaultTarget::Motor, FaultKind::OverVoltage, "over_voltage", false, 0, 0, 0},
    // the phase the driver names (MotorPhase: A, B, C); A when not given, the seed's bit 17
    {FaultTarget::Motor, FaultKind::OverCurrent, "over_current", true, 0, 2, 0, false, "ABC"},
    // which of the driver's eight overload bits
    {FaultTarget::Motor, FaultKind::Overload, "overload", true, 1, kMotorOverloadKinds, 1, true},
    {FaultTarget::Motor, FaultKind::EncoderLost, "encoder_lost", false, 0, 0, 0},
    {FaultTarget::Motor, FaultKind::Stuck, "stuck", false, 0, 0, 0},
    {FaultTarget::Motor, FaultKind::Derated, "derated", true, 0.0, 1.0, kRequired},
    {FaultTarget::Motor, FaultKind::Hot, "hot", true, 20.0, 120.0, kRequired},
    {FaultTarget::Imu, FaultKind::ImuBias, "bias", true, -1.0, 1.0, kRequired},
    {FaultTarget::Imu, FaultKind::ImuStuck, "stuck", false, 0, 0, 0},
    {FaultTarget::Imu, FaultKind::ImuDropout, "dropout", false, 0, 0, 0},
    {FaultTarget::Imu, FaultKind::ImuNan, "nan", false, 0, 0, 0},
    {FaultTarget::Battery, FaultKind::BatteryStateOfCharge, "soc", true, 0.0, 100.0, kRequired},
    {FaultTarget::Battery, FaultKind::BatteryDrain, "drain", true, 0.0, 1000.0, kRequired},
    {FaultTarget::Battery, FaultKind::BatteryCapacity, "capacity", true, 0.01, 100.0, kRequired},
    {FaultTarget::Battery, FaultKind::BatterySag, "sag", true, 0.0, 25.0, kRequired},
    {FaultTarget::Foot, FaultKind::Slippery, "slippery", true, 0.0, 2.0, 0.05},
}};

constexpr double kDurationMaxS = 3600.0;

const char* target_word(FaultTarget target) {
  switch (target) {
    case FaultTarget::Motor: return "motor";
    case FaultTarget::Imu: return "imu";
    case FaultTarget::Battery: return "battery";
    case FaultTarget::Foot: return "foot";
    case FaultTarget::All: return "";
  }
  return "";
}

// 12 significant digits: what a person or a file writes reads back unchanged
std::string format_number(double value) { return number_text(value, 12); }

// "5" or "FR_knee" -> 0..11; "2" or "RR" -> 0..3 (legs)
std::optional<int> motor_index(const std::string& word) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      if (word == std::string(kLegNames[leg]) + "_" + kJointNames[joint])
        return static_cast<int>(joint_index(leg, joint));
    }
  }
  const std::optional<double> value = finite_number(word);
  if (value && *value == std::floor(*value) && *value >= 0 && *value < static_cast<double>(kNumJoints)) {
    return static_cast<int>(*value);
  }
  return std::nullopt;
}

std::optional<int> leg_index(const std::string& word) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (word == kLegNames[leg]) return static_cast<int>(leg);
  }
  const std::optional<double> value = finite_number(word);
  if (value && *value == std::floor(*value) && *value >= 0 && *value < static_cast<double>(kNumLegs)) {
    return static_cast<int>(*value);
  }
  return std::nullopt;
}

std::string clip(const std::string& word) { return word.substr(0, 32); }

// "ABC" -> "A|B|C"
std::string letter_choices(const char* letters) {
  std::string out;
  for (const char* c = letters; *c != '\0'; ++c) {
    if (!out.empty()) out += '|';
    out += *c;
  }
  return out;
}

// the index of a one-letter word in letters
std::optional<double> letter_index(const std::string& word, const char* letters) {
  const std::string all = letters;
  const std::size_t at = word.size() == 1 ? all.find(word[0]) : std::string::npos;
  if (at == std::string::npos) return std::nullopt;
  return static_cast<double>(at);
}

std::string value_text(const KindWord& kind, double value) {
  const std::string letters = kind.letters != nullptr ? kind.letters : "";
  if (letters.empty()) return format_number(value);
  const auto at = static_cast<std::size_t>(std::clamp(value, 0.0, static_cast<double>(letters.size() - 1)));
  return letters.substr(at, 1);
}

FaultParse failure(const std::string& why) { return FaultParse{std::nullopt, why}; }

std::string kinds_of(FaultTarget target) {
  std::string out;
  for (const KindWord& k : kKinds) {
    if (k.target == target) out += (out.empty() ? "" : ", ") + std::string(k.word);
  }
  return out;
}

}  // namespace

const char* fault_grammar() {
  return "motor N disconnected|over_temperature|driver_fault|under_voltage|over_voltage|over_current [A|B|C]|"
         "overload [1..8]|encoder_lost|stuck|derated FRACTION|hot DEG_C; imu bias RAD_S|stuck|dropout|nan; "
         "battery soc PERCENT|drain FACTOR|capacity AH|sag VOLTS; foot LEG slippery [MU]; "
         "clear [motor N|imu|battery|foot LEG]; "
         "each optionally followed by: for SECONDS";
}

FaultParse parse_fault(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return parse_fault(words);
}

FaultParse parse_fault(const std::vector<std::string>& all_words) {
  std::vector<std::string> words = all_words;
  FaultRequest request;
  // a trailing "for SECONDS"
  if (words.size() >= 2 && words[words.size() - 2] == "for") {
    const std::optional<double> duration = finite_number(words.back());
    if (!duration || !(*duration > 0.0 && *duration <= kDurationMaxS)) {
      return failure("for SECONDS must be in (0, " + format_number(kDurationMaxS) + "], got '" + clip(words.back()) +
                     "'");
    }
    request.duration_s = *duration;
    words.resize(words.size() - 2);
  }
  if (words.empty()) return failure(std::string("no fault given (accepted: ") + fault_grammar() + ")");
  const std::string& head = words[0];
  std::size_t next = 1;
  if (head == "clear") {
    request.kind = FaultKind::Clear;
    if (request.duration_s > 0.0) return failure("clear takes no duration");
    if (words.size() == 1) return FaultParse{request, ""};
    const std::string& what = words[1];
    if (what == "imu" || what == "battery") {
      if (words.size() != 2) return failure("clear " + what + " takes nothing more");
      request.target = what == "imu" ? FaultTarget::Imu : FaultTarget::Battery;
      return FaultParse{request, ""};
    }
    if (what != "motor" && what != "foot") {
      return failure("clear what: '" + clip(what) +
                     "' (accepted: clear, clear motor N, clear imu, clear battery, clear foot LEG)");
    }
    if (words.size() != 3) return failure("clear " + what + " takes one " + (what == "motor" ? "motor N" : "LEG"));
    const std::optional<int> index = what == "motor" ? motor_index(words[2]) : leg_index(words[2]);
    if (!index) {
      return failure(what == "motor" ? "motor must be 0..11 or a name like FR_knee, got '" + clip(words[2]) + "'"
                                     : "leg must be 0..3 or FR, FL, RR, RL, got '" + clip(words[2]) + "'");
    }
    request.target = what == "motor" ? FaultTarget::Motor : FaultTarget::Foot;
    request.index = *index;
    return FaultParse{request, ""};
  }
  if (head == "motor" || head == "foot") {
    request.target = head == "motor" ? FaultTarget::Motor : FaultTarget::Foot;
    if (words.size() < 3) {
      return failure(head == "motor" ? "motor N FAULT: the motor and the fault are missing (faults: " +
                                           kinds_of(FaultTarget::Motor) + ")"
                                     : "foot LEG slippery [MU]: the leg and the fault are missing");
    }
    const std::optional<int> index = head == "motor" ? motor_index(words[1]) : leg_index(words[1]);
    if (!index) {
      return failure(head == "motor" ? "motor must be 0..11 or a name like FR_knee, got '" + clip(words[1]) + "'"
                                     : "leg must be 0..3 or FR, FL, RR, RL, got '" + clip(words[1]) + "'");
    }
    request.index = *index;
    next = 2;
  } else if (head == "imu" || head == "battery") {
    request.target = head == "imu" ? FaultTarget::Imu : FaultTarget::Battery;
    if (words.size() < 2)
      return failure(head + " FAULT: the fault is missing (faults: " + kinds_of(request.target) + ")");
  } else if (head == "link") {
    return failure(
        "link faults act on the interfaces, not the robot: set them at run time with `cerebellum fault link ...`");
  } else {
    return failure("unknown component '" + clip(head) + "' (accepted: motor, imu, battery, foot, clear)");
  }
  const std::string& kind_word = words[next];
  const KindWord* kind = nullptr;
  for (const KindWord& k : kKinds) {
    if (k.target == request.target && kind_word == k.word) kind = &k;
  }
  if (kind == nullptr) {
    return failure("unknown " + head + " fault '" + clip(kind_word) + "' (accepted: " + kinds_of(request.target) + ")");
  }
  request.kind = kind->kind;
  const std::size_t values = words.size() - next - 1;
  if (!kind->takes_value) {
    if (values != 0) return failure(head + " " + kind->word + " takes no value");
    return FaultParse{request, ""};
  }
  if (values > 1) return failure(head + " " + kind->word + " takes one value");
  if (values == 0) {
    if (std::isnan(kind->fallback)) {
      return failure(head + " " + kind->word + " needs a value in [" + format_number(kind->lower) + ", " +
                     format_number(kind->upper) + "]");
    }
    request.value = kind->fallback;
    return FaultParse{request, ""};
  }
  if (kind->letters != nullptr) {
    const std::optional<double> index = letter_index(words[next + 1], kind->letters);
    if (!index) {
      return failure(head + " " + kind->word + " value must be " + letter_choices(kind->letters) + ", got '" +
                     clip(words[next + 1]) + "'");
    }
    request.value = *index;
    return FaultParse{request, ""};
  }
  const std::optional<double> value = finite_number(words[next + 1]);
  if (!value || *value < kind->lower || *value > kind->upper || (kind->whole && *value != std::floor(*value))) {
    return failure(head + " " + kind->word + " value must be " + (kind->whole ? "a whole number" : "a number") +
                   " in [" + format_number(kind->lower) + ", " + format_number(kind->upper) + "], got '" +
                   clip(words[next + 1]) + "'");
  }
  request.value = *value;
  return FaultParse{request, ""};
}

std::string fault_text(const FaultRequest& request) {
  // appended word by word (GCC 12 warns falsely about " " + std::string temporaries)
  std::string text;
  const auto word = [&text](const std::string& w) {
    if (!text.empty()) text += ' ';
    text += w;
  };
  if (request.kind == FaultKind::Clear) {
    word("clear");
    if (request.target != FaultTarget::All) word(target_word(request.target));
    if (request.index >= 0) word(std::to_string(request.index));
    return text;
  }
  word(target_word(request.target));
  if (request.index >= 0) word(std::to_string(request.index));
  for (const KindWord& k : kKinds) {
    if (k.target == request.target && k.kind == request.kind) {
      word(k.word);
      if (k.takes_value) word(value_text(k, request.value));
    }
  }
  if (request.duration_s > 0.0) {
    word("for");
    word(format_number(request.duration_s));
  }
  return text;
}

}  // namespace cerebellum
