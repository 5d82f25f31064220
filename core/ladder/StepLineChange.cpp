// SPDX-License-Identifier: GPL-3.0-or-later
#include "StepLineChange.h"

#include "TextToLadder.h"
#include "blocks/BlockInstance.h"
#include "project/Annotation.h"

#include <algorithm>
#include <iterator>

namespace rs::ladder {

namespace {

bool isInstanceRecord(const lang::Line& line) {
    const auto record = project::annotationOn(line);
    return record && (record->kind == blocks::kBlockRecord || record->kind == blocks::kEndRecord);
}

std::int64_t statementsOf(std::span<const Network> networks) {
    std::int64_t count = 0;
    for (const auto& network : networks)
        count += statementCount(network);
    return count;
}

} // namespace

std::optional<NetworkRunChange> followLineChange(StepPage& page, const lang::Step& step,
                                                 std::size_t first,
                                                 std::span<const lang::Line> removed,
                                                 std::size_t added) {
    std::vector<Network>& networks = page.ladder.networks;
    const std::size_t leading = page.ladder.leading.size();
    // Where each network starts among the step's lines as they were.
    std::vector<std::size_t> starts;
    starts.reserve(networks.size() + 1);
    std::size_t line = leading;
    for (const auto& network : networks) {
        if (network.block)
            return std::nullopt;
        starts.push_back(line);
        line += lineCount(network);
    }
    starts.push_back(line);
    const std::size_t end = first + removed.size();
    if (end > line || step.lines.size() != line - removed.size() + added)
        return std::nullopt; // not the step this page shows
    const auto addedLines = step.lines.begin() + static_cast<std::ptrdiff_t>(first);
    if (std::any_of(removed.begin(), removed.end(), isInstanceRecord) ||
        std::any_of(addedLines, addedLines + static_cast<std::ptrdiff_t>(added), isInstanceRecord))
        return std::nullopt;

    // From the network holding the line before the run (lines added after a
    // network's last line may be its comments) to the last the run touches;
    // the leading lines too when the run begins among them.
    const bool fromLeading = first <= leading;
    std::size_t from = fromLeading
                           ? 0
                           : static_cast<std::size_t>(
                                 std::upper_bound(starts.begin(), starts.end() - 1, first - 1) -
                                 starts.begin() - 1);
    std::size_t to = static_cast<std::size_t>(
        std::lower_bound(starts.begin() + static_cast<std::ptrdiff_t>(from), starts.end() - 1,
                         end) -
        starts.begin());
    const std::size_t begin = fromLeading ? 0 : starts[from];
    StepLadder read;
    for (;;) {
        const std::size_t stop =
            to < networks.size() ? starts[to] - removed.size() + added : step.lines.size();
        lang::Step part{step.address,
                        step.comment,
                        step.location,
                        {step.lines.begin() + static_cast<std::ptrdiff_t>(begin),
                         step.lines.begin() + static_cast<std::ptrdiff_t>(stop)}};
        read = toLadder(part);
        // A network without a record begins at its statement only where the
        // network before it has no record; else the statement joins it.
        if (to < networks.size() && !networks[to].record && !read.networks.empty() &&
            read.networks.back().record) {
            ++to;
            continue;
        }
        break;
    }
    if (!fromLeading && !read.leading.empty())
        return std::nullopt;
    // The networks read again that are what they were stay, with their items.
    std::size_t same = 0;
    while (from + same < to && same < read.networks.size() &&
           read.networks[same] == networks[from + same])
        ++same;
    read.networks.erase(read.networks.begin(),
                        read.networks.begin() + static_cast<std::ptrdiff_t>(same));
    from += same;
    while (from < to && !read.networks.empty() && read.networks.back() == networks[to - 1]) {
        read.networks.pop_back();
        --to;
    }

    const auto at = [](auto& vector, std::size_t index) {
        return vector.begin() + static_cast<std::ptrdiff_t>(index);
    };
    const std::int64_t shift =
        statementsOf(read.networks) -
        statementsOf(std::span<const Network>(networks).subspan(from, to - from));
    std::uint32_t statement =
        from < networks.size() ? page.firstStatements[from]
        : from > 0             ? page.firstStatements[from - 1] +
                         static_cast<std::uint32_t>(statementCount(networks[from - 1]))
                   : page.firstStatement;
    std::vector<std::uint32_t> numbers;
    numbers.reserve(read.networks.size());
    for (const auto& network : read.networks) {
        numbers.push_back(statement);
        statement += static_cast<std::uint32_t>(statementCount(network));
    }
    for (auto number = at(page.firstStatements, to); number != page.firstStatements.end(); ++number)
        *number = static_cast<std::uint32_t>(*number + shift);
    page.firstStatements.erase(at(page.firstStatements, from), at(page.firstStatements, to));
    page.firstStatements.insert(at(page.firstStatements, from), numbers.begin(), numbers.end());

    const NetworkRunChange change{from, to - from, read.networks.size(), shift};
    networks.erase(at(networks, from), at(networks, to));
    networks.insert(at(networks, from), std::make_move_iterator(read.networks.begin()),
                    std::make_move_iterator(read.networks.end()));
    if (fromLeading)
        page.ladder.leading = std::move(read.leading);
    return change;
}

} // namespace rs::ladder
