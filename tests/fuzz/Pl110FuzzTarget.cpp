// SPDX-License-Identifier: GPL-3.0-or-later
// The PL110 text form: any input is read without a crash, every diagnostic
// points into the text, a program read without errors prints to a text that
// reads back to the same program, and a checked program scans. The same
// bytes go to the Modbus slave map as a request (docs/pl110.md).
#include "FuzzFailure.h"

#include "pl110/ModbusSlave.h"
#include "pl110/ProgramCheck.h"
#include "pl110/ProgramText.h"
#include "pl110/ScanEngine.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rs;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const pl110::ProgramReading reading = pl110::readProgram(text);
    fuzz::requireInside(text, reading.diagnostics, "a reading diagnostic points outside the text");

    pl110::Memory memory;
    const std::vector<std::uint8_t> answer = pl110::answerRequest(memory, {data, size});
    if (answer.empty())
        fuzz::fail("the Modbus slave gave no answer");

    if (!reading.diagnostics.empty())
        return 0;
    const std::string printed = pl110::printProgram(reading.program);
    const pl110::ProgramReading again = pl110::readProgram(printed);
    if (!again.diagnostics.empty() || !(again.program == reading.program))
        fuzz::fail("the printed program does not read back to the same program");
    if (pl110::printProgram(again.program) != printed)
        fuzz::fail("printing is not idempotent");
    const lang::Diagnostics checked = pl110::checkProgram(reading.program);
    fuzz::requireInside(text, checked, "a check diagnostic points outside the text");
    if (checked.empty()) {
        pl110::ScanEngine engine(reading.program);
        for (int scan = 0; scan < 4; ++scan)
            engine.scan();
    }
    return 0;
}
