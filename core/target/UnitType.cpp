// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitType.h"

#include "lang/Keywords.h"
#include "lang/SymbolicName.h"
#include "lang/TextCase.h"

namespace rs::target {

namespace {

using lang::AddressKind;

SystemVariable named(std::string_view name, std::string_view function,
                     Access access = Access::Read) {
    lang::Address address = lang::systemName(name, 0);
    return {address.kind, address.index, name, function, access};
}

std::vector<SystemVariable> common() {
    std::vector<SystemVariable> list{
        named("SM_StepNew", "On at first scan in new sequence step"),
        named("SM_Ditto", "Result of last logic operation"),
        named("SM_Flash", "Flash: 0.4 / 0.6 s (on/off)"),
        named("SM_1Hz", "Pulse 1 Hz"),
        named("SM_10Hz", "Pulse 10 Hz"),
        named("SM_FastFlash", "Flash: 0.17 / 0.33 s (on/off)"),
        named("SM_DoubleFlash", "Double flash: 0.11 / 0.2 / 0.11 / 0.67 s"),
        named("SM_SysInit", "On at first scan after power on"),
        named("SM_TimerFreeze", "Freeze timer (next timer in program code)", Access::Write),
        named("SM_Overflow", "Overflow in arithmetic"),
        named("SM_DivByZero", "Divide by zero"),
        named("SM_Button", "Button in front panel"),
        named("SR_Remain", "Remain part after division"),
        named("SR_ExecFreeTime", "PLC cycle time left to be used (µs)"),
        named("SR_ExecTime", "PLC execution time in µs"),
        named("SR_PlutoDisplay", "Pluto display figure; for user error: 200+no", Access::Write),
        named("SR_ErrorCode", "Error code"),
        named("SR_ErrorLog1", "Last error code"),
        named("SR_ErrorLog2", "2nd last error code"),
        named("SR_ErrorLog3", "3rd last error code"),
        named("SR_SupplVolt", "Supply voltage (x10 V)"),
    };
    // SM_Pluto0_Present .. SM_Pluto31_Present; the names are built by lang::systemName.
    static const std::vector<std::string> presentNames = [] {
        std::vector<std::string> names;
        for (int station = 0; station < 32; ++station)
            names.push_back("SM_Pluto" + std::to_string(station) + "_Present");
        return names;
    }();
    for (const auto& name : presentNames)
        list.push_back(named(name, "Pluto unit is present on the bus"));
    return list;
}

std::vector<SystemVariable> with(std::vector<SystemVariable> extra, int plutoBIndex) {
    std::vector<SystemVariable> list = common();
    list.push_back({AddressKind::SystemMemory, plutoBIndex, "SM_PlutoB",
                    "This is Pluto B processor", Access::Read});
    list.insert(list.end(), extra.begin(), extra.end());
    return list;
}

static_assert(lang::kUnitTypeWords.size() == static_cast<std::size_t>(UnitType::B42ASi) + 1);

// The name type_pluto gives the type, from the language's table of words.
std::string_view typeWord(UnitType type) {
    return lang::kUnitTypeWords[static_cast<std::size_t>(type)];
}

constexpr int kA20PlutoB = 84;   // "A20 family only"
constexpr int kOtherPlutoB = 15; // "B46, D45, AS-i and B42 AS-i only"

UnitTypeInfo a20Family(UnitType type, std::vector<SystemVariable> extra) {
    UnitTypeInfo info{type, typeWord(type), typeWord(type), lang::UnitFamily::Pluto};
    info.globalInputs = {{0, 7}, {10, 17}};
    info.globalSafetyOutputs = {{0, 3}};
    info.nonSafetyOutputs = {{10, 17}};
    info.configurableTerminals = {{10, 17}};
    info.remanent = true;
    info.systemVariables = with(std::move(extra), kA20PlutoB);
    return info;
}

std::vector<UnitTypeInfo> buildTable() {
    const SystemVariable i5 = named("SR_I5_Volt", "Voltage analogue input I5 (x10 V)");
    std::vector<UnitTypeInfo> table;

    // A16 and B16 are listed with the A20 family (gateway manual); the
    // programming manual gives them no table of their own, and no remanent
    // variables or test-pulse option (appendix A).
    UnitTypeInfo a16 = a20Family(UnitType::A16, {i5});
    a16.remanent = false;
    table.push_back(a16);
    UnitTypeInfo a20 =
        a20Family(UnitType::A20, {i5, named("SR_Q16_Current", "Current (mA) output Q16"),
                                  named("SR_Q17_Current", "Current (mA) output Q17")});
    a20.testPulsesCanBeDisabled = true;
    table.push_back(a20);
    UnitTypeInfo b16 = a20Family(UnitType::B16, {i5});
    b16.remanent = false;
    table.push_back(b16);
    UnitTypeInfo b20 = a20Family(UnitType::B20, {i5});
    b20.testPulsesCanBeDisabled = true;
    table.push_back(b20);
    UnitTypeInfo s20 = a20Family(UnitType::S20, {i5});
    s20.testPulsesCanBeDisabled = true;
    table.push_back(s20);

    UnitTypeInfo b22 = a20Family(UnitType::B22, {i5});
    b22.globalSafetyOutputs = {};
    b22.localInputs = {{20, 25}};
    table.push_back(b22);

    UnitTypeInfo d20 = a20Family(UnitType::D20, {i5});
    d20.globalInputs = {{4, 7}, {10, 17}};
    d20.analogInputs = {{0, 3}};
    d20.testPulsesCanBeDisabled = true;
    table.push_back(d20);

    UnitTypeInfo o2 = a20Family(UnitType::O2, {});
    o2.remanent = false;
    table.push_back(o2);

    auto doubleFamily = [&](UnitType type, bool d45) {
        UnitTypeInfo info{type, typeWord(type), typeWord(type), lang::UnitFamily::Double};
        info.globalInputs = d45 ? Ranges{{10, 17}} : Ranges{{0, 7}, {10, 17}};
        info.analogInputs = d45 ? Ranges{{0, 7}} : Ranges{};
        info.counterInputs = d45 ? Ranges{{0, 3}} : Ranges{};
        info.localInputs =
            d45 ? Ranges{{20, 26}, {30, 37}, {40, 47}} : Ranges{{20, 27}, {30, 37}, {40, 47}};
        info.globalSafetyOutputs = {{0, 3}};
        info.localSafetyOutputs = {{4, 5}};
        info.nonSafetyOutputs = d45 ? Ranges{{10, 17}, {20, 26}} : Ranges{{10, 17}, {20, 27}};
        info.configurableTerminals = info.nonSafetyOutputs;
        info.remanent = true;
        info.systemVariables =
            with({i5, named("SR_I6_Volt", "Voltage at analogue input I6 (x10 V)"),
                  named("SR_I7_Volt", "Voltage at analogue input I7 (x10 V)")},
                 kOtherPlutoB);
        return info;
    };
    table.push_back(doubleFamily(UnitType::B46, false));
    table.push_back(doubleFamily(UnitType::S46, false));
    table.push_back(doubleFamily(UnitType::D45, true));

    UnitTypeInfo asi{UnitType::ASi, typeWord(UnitType::ASi), "AS-i", lang::UnitFamily::ASi};
    asi.globalInputs = {{0, 0}};
    asi.localInputs = {{1, 3}, {10, 13}};
    asi.asiGlobalSafeInputs = {{1, 15}};
    asi.asiLocalSafeInputs = {{16, 31}};
    asi.asiSlaves = true;
    asi.globalSafetyOutputs = {{0, 3}};
    asi.nonSafetyOutputs = {{10, 13}};
    asi.configurableTerminals = {{10, 13}};
    asi.memoriesInstructionSet2 = 150;
    asi.remanent = true;
    asi.systemVariables =
        with({named("SR_ASi_Slave_Missing", "First AS-i slave missing; B slave as no+32"),
              named("SR_ASi_Slave_Chanf", "First AS-i slave channel fault; B slave as no+32"),
              named("SR_IQ11_Volt", "Voltage analogue input IQ11 (x10 V)"),
              named("SR_IQ10_Volt", "Voltage at analogue input IQ10 (x10 V)"),
              named("SR_IQ12_Volt", "Voltage at analogue input IQ12 (x10 V)"),
              named("SR_IQ13_Volt", "Voltage at analogue input IQ13 (x10 V)")},
             kOtherPlutoB);
    table.push_back(asi);

    UnitTypeInfo b42{UnitType::B42ASi, typeWord(UnitType::B42ASi), "B42 AS-i",
                     lang::UnitFamily::B42ASi};
    b42.globalInputs = {{0, 3}};
    b42.localInputs = {{10, 17}, {20, 27}, {30, 37}, {40, 47}};
    b42.asiLocalSafeInputs = {{1, 31}};
    b42.asiSlaves = true;
    b42.localSafetyOutputs = {{0, 5}};
    b42.nonSafetyOutputs = {{10, 17}, {20, 27}};
    b42.configurableTerminals = b42.nonSafetyOutputs;
    b42.globalMemories = 28;
    b42.remanent = true;
    b42.systemVariables =
        with({named("SR_ASi_Slave_Missing", "First AS-i slave missing; B slave as no+32"),
              named("SR_ASi_Slave_Chanf", "First AS-i slave channel fault; B slave as no+32"),
              named("SR_I1_Volt", "Voltage at analogue input I1 (x10 V)"),
              named("SR_I2_Volt", "Voltage at analogue input I2 (x10 V)"),
              named("SR_I3_Volt", "Voltage at analogue input I3 (x10 V)")},
             kOtherPlutoB);
    table.push_back(b42);
    return table;
}

} // namespace

bool contains(const Ranges& ranges, int n) {
    for (const auto& range : ranges)
        if (range.contains(n))
            return true;
    return false;
}

const std::vector<UnitTypeInfo>& unitTypes() {
    static const std::vector<UnitTypeInfo> table = buildTable();
    return table;
}

const UnitTypeInfo& unitTypeInfo(UnitType type) {
    return unitTypes()[static_cast<std::size_t>(type)];
}

const UnitTypeInfo* findUnitType(std::string_view name) {
    const std::string upper = lang::toUpper(name);
    for (const auto& info : unitTypes())
        if (lang::toUpper(info.name) == upper)
            return &info;
    return nullptr;
}

UnitType baseType(lang::UnitFamily family) {
    switch (family) {
    case lang::UnitFamily::Pluto:
        return UnitType::A20;
    case lang::UnitFamily::Double:
        return UnitType::B46;
    case lang::UnitFamily::ASi:
        return UnitType::ASi;
    case lang::UnitFamily::B42ASi:
        return UnitType::B42ASi;
    }
    return UnitType::A20;
}

std::string withArticle(const UnitTypeInfo& info) {
    // Said letter by letter: "an A20", "an O2", "an S46", "a B46", "a D20".
    const char first = info.display.empty() ? 'B' : info.display.front();
    return std::string(first == 'A' || first == 'O' || first == 'S' ? "an " : "a ") +
           std::string(info.display);
}

int memoryCount(const UnitTypeInfo& info, int instructionSet) {
    return instructionSet >= 3 ? info.memoriesInstructionSet3 : info.memoriesInstructionSet2;
}

bool hasVariable(const UnitTypeInfo& info, const lang::Address& a, int instructionSet) {
    switch (a.kind) {
    case AddressKind::Input:
        return contains(info.globalInputs, a.index) || contains(info.localInputs, a.index);
    case AddressKind::Output:
        return contains(info.globalSafetyOutputs, a.index) ||
               contains(info.localSafetyOutputs, a.index) ||
               contains(info.nonSafetyOutputs, a.index);
    case AddressKind::InputOutput:
        return contains(info.configurableTerminals, a.index);
    case AddressKind::AnalogInput:
        return contains(info.analogInputs, a.index);
    case AddressKind::Memory:
        return a.index < memoryCount(info, instructionSet);
    case AddressKind::GlobalMemory:
        return a.index < info.globalMemories;
    case AddressKind::SystemMemory:
        return a.index < info.systemMemories;
    case AddressKind::Register:
        return a.index < info.registers;
    case AddressKind::RegisterBit:
        return a.index < info.registers && a.bit >= 0 && a.bit <= 15;
    case AddressKind::DoubleRegister:
    case AddressKind::DoubleRegisterLow:
    case AddressKind::DoubleRegisterHigh:
        return a.index % 2 == 0 && a.index + 1 < info.registers;
    case AddressKind::SystemRegister:
        return a.index < info.systemRegisters;
    case AddressKind::AsiInput:
        if (a.bit < 0)
            return !a.asiB && (contains(info.asiGlobalSafeInputs, a.index) ||
                               contains(info.asiLocalSafeInputs, a.index));
        [[fallthrough]];
    case AddressKind::AsiOutput:
        return info.asiSlaves && a.index >= 1 && a.index <= 31 && a.bit >= 1 && a.bit <= 4;
    case AddressKind::Sequence:
        return a.index >= 1 && a.index <= 9;
    case AddressKind::None:
        return false;
    }
    return false;
}

bool isGlobal(const UnitTypeInfo& info, const lang::Address& a) {
    switch (a.kind) {
    case AddressKind::Input:
        return contains(info.globalInputs, a.index);
    case AddressKind::AnalogInput:
        return contains(info.analogInputs, a.index);
    case AddressKind::Output:
        return contains(info.globalSafetyOutputs, a.index);
    case AddressKind::InputOutput:
        return contains(info.globalInputs, a.index);
    case AddressKind::GlobalMemory:
        return true;
    case AddressKind::AsiInput:
        return a.bit < 0 && contains(info.asiGlobalSafeInputs, a.index);
    default:
        return false;
    }
}

const SystemVariable* systemVariable(const UnitTypeInfo& info, const lang::Address& a) {
    for (const auto& variable : info.systemVariables)
        if (variable.kind == a.kind && variable.index == a.index)
            return &variable;
    return nullptr;
}

std::optional<std::string_view> instructionSet3Feature(const lang::Address& a) {
    switch (a.kind) {
    case AddressKind::RegisterBit:
        return "register bits";
    case AddressKind::DoubleRegister:
    case AddressKind::DoubleRegisterLow:
    case AddressKind::DoubleRegisterHigh:
        return "double registers";
    default:
        return std::nullopt;
    }
}

} // namespace rs::target
