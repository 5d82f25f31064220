// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"
#include "target/UnitType.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The AS-i Options page of a Pluto AS-i or B42 AS-i as data (manual Part 1,
// 7.1.2-7.1.4): how the unit works on the AS-i bus and what each slave
// address holds. It decides which AS-i variables a unit has, what the
// compiler warns about, and how the simulator turns a safe input slave's two
// channels into its input.
namespace rs::project {

// "AS-i bus working mode".
enum class AsiMode {
    Master,            // Pluto is the bus master and can set non-safety slaves' outputs
    MonitorOnly,       // an external master controls the bus; Pluto listens
    MonitorSlave,      // as MonitorOnly, and Pluto is a slave of the external master
    MonitorSlaveExtra, // as MonitorSlave, with three extra virtual slaves
    Unused,            // the AS-i bus is not used
};

// "Optimize for".
enum class AsiOptimisation { ShortStopTime, DisturbanceImmunity };

// "Type of Slave": the manual's eight choices.
enum class AsiSlaveType {
    Undefined,
    SafeInput,
    NonsafeStandard,
    NonsafeAB, // "Nonsafe A" on an A address, "Nonsafe B" on a B address
    CombinedTransaction,
    Analogue,
    SafeOutput,
    PlutoAsSafeInput,
};

// "Channel Monitoring" of a safe input slave's two channels.
enum class ChannelMonitoring {
    None,                 // both channels must be on
    Monitoring,           // one channel open: the other must open too before both close again
    MonitoringDebounce,   // as Monitoring, but bounces within the time limit after both closed
    Simultaneous,         // as Monitoring, and the second must close within the time limit
    SimultaneousDebounce, // as Simultaneous, with bounces allowed within the time limit
};

// A slave address: 1-31, an A (or single) slave or a B slave.
struct AsiSlaveAddress {
    int number = 1;
    bool b = false;

    friend auto operator<=>(const AsiSlaveAddress&, const AsiSlaveAddress&) = default;
};

// The profile "S-7.B.F ID1=F": I/O configuration, ID code, ID2 and ID1, each
// one hexadecimal digit.
struct AsiProfile {
    int io = 0;
    int id = 0xB;
    int id2 = 0xF;
    int id1 = 0xF;

    friend bool operator==(const AsiProfile&, const AsiProfile&) = default;
};

struct AsiSlave {
    AsiSlaveType type = AsiSlaveType::Undefined;
    std::string model{"General"}; // safe input slaves: General or a URAX model
    int parameter = 0xF;          // "Param", one hexadecimal digit
    AsiProfile profile;
    ChannelMonitoring monitoring = ChannelMonitoring::Monitoring;
    int timeLimitMs = 1000; // "Time limit", for the simultaneous and debounce modes

    friend bool operator==(const AsiSlave&, const AsiSlave&) = default;
};

struct AsiOptions {
    AsiMode mode = AsiMode::Master;
    int slaveAddress = 1; // Pluto's own address in the monitor/slave modes, 1-31
    AsiOptimisation optimisation = AsiOptimisation::ShortStopTime;
    std::map<AsiSlaveAddress, AsiSlave> slaves; // defined slaves only

    friend bool operator==(const AsiOptions&, const AsiOptions&) = default;
};

// Limits Rungsmith enforces; the manual gives no range for the time limit.
inline constexpr int kAsiSlaveCount = 31;
inline constexpr int kMinAsiTimeLimitMs = 10;
inline constexpr int kMaxAsiTimeLimitMs = 10'000;
// "Pluto can handle up to 16 PlutoAsSafeInput + SafeOutput slaves."
inline constexpr int kMaxAsiBlockSlaves = 16;

// The models of a safe input slave the manual names; every URAX model but
// URAX-C1 monitors its channels itself.
const std::vector<std::string_view>& asiSafeInputModels();
bool monitorsOwnChannels(std::string_view model);

// "ASi0.3", "ASi0.3B".
std::string slaveLabel(int station, AsiSlaveAddress slave);
// Reads "ASi0.3B" (case-insensitive); nothing when it is no slave address.
std::optional<std::pair<int, AsiSlaveAddress>> readSlaveLabel(std::string_view word);

// "S-0.B.F ID1=F".
std::string profileText(const AsiProfile& profile);

// The types an address offers given the slave on the A address with the same
// number: a B address takes only A/B slaves, and only beside an A/B slave or
// none.
std::vector<AsiSlaveType> slaveTypesAt(AsiSlaveAddress address, AsiSlaveType aSlave);
bool hasProfile(AsiSlaveType type, std::string_view model);
bool hasChannels(AsiSlaveType type); // a dual-channel safe input
bool usesTimeLimit(ChannelMonitoring monitoring);

// A new slave of the type with the defaults the page starts it with.
AsiSlave defaultSlave(AsiSlaveType type);

// Sets the slave at an address (Undefined removes it) and keeps the options
// consistent: a B slave goes when its A address takes a type that fills the
// whole address. Returns why it was refused, and then changes nothing: a type
// the address does not offer, a value out of its range, more than
// kMaxAsiBlockSlaves safe output and Pluto-as-safe-input slaves.
std::optional<std::string> setSlave(AsiOptions& options, AsiSlaveAddress address,
                                    const AsiSlave& slave);

// The variables the manual's table gives a slave of this type on this unit:
// ASi_.x for a safe input, ASi_.x.n inputs and ASq_.x.n outputs.
std::vector<lang::Address> slaveVariables(const target::UnitTypeInfo& type, int station,
                                          AsiSlaveAddress address, AsiSlaveType slaveType);

// The slave an AS-i variable belongs to.
AsiSlaveAddress slaveOf(const lang::Address& address);

// The manual's name of a type: "Safe Input", "Nonsafe Std".
std::string_view slaveTypeName(AsiSlaveType type);

// Words of the project file's records (docs/file-format.md).
std::string_view modeWord(AsiMode mode);
std::string_view optimisationWord(AsiOptimisation optimisation);
std::string_view slaveTypeWord(AsiSlaveType type);
std::string_view monitoringWord(ChannelMonitoring monitoring);
std::optional<AsiMode> modeOfWord(std::string_view word);
std::optional<AsiOptimisation> optimisationOfWord(std::string_view word);
std::optional<AsiSlaveType> slaveTypeOfWord(std::string_view word);
std::optional<ChannelMonitoring> monitoringOfWord(std::string_view word);
std::optional<AsiProfile> readProfile(std::string_view text); // "S-0.B.F"
std::string profileWord(const AsiProfile& profile);           // "S-0.B.F"

} // namespace rs::project
