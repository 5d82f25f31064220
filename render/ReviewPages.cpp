// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReviewPages.h"

#include "compiler/Signature.h"
#include "ladder/ProjectLadder.h"

#include <QDate>
#include <QFileInfo>

#include <map>
#include <utility>

namespace rs::render {

Review reviewPages(const ReviewedVersion& before, const ReviewedVersion& after,
                   const review::ProjectDiff& diff, const QString& comparedBy) {
    Review review;
    review.title = QStringLiteral("Review of %1").arg(QFileInfo(after.path).fileName());
    const auto signature = [](std::uint32_t value) {
        return QString::fromStdString(compiler::signatureText(value));
    };
    review.summary << QStringLiteral("Old: %1, project signature %2")
                          .arg(before.path, signature(before.compiled.projectSignature))
                   << QStringLiteral("New: %1, project signature %2")
                          .arg(after.path, signature(after.compiled.projectSignature));
    std::map<int, std::pair<QString, QString>> units;
    for (const auto& unit : before.compiled.signatures)
        units[unit.station].first = signature(unit.value);
    for (const auto& unit : after.compiled.signatures)
        units[unit.station].second = signature(unit.value);
    for (const auto& [station, figures] : units)
        review.summary << QStringLiteral("Pluto %1: %2 → %3")
                              .arg(station, 2, 10, QLatin1Char('0'))
                              .arg(figures.first.isEmpty() ? QStringLiteral("none") : figures.first,
                                   figures.second.isEmpty() ? QStringLiteral("none")
                                                            : figures.second);
    review.summary << QStringLiteral("Compared on %1 by %2")
                          .arg(QDate::currentDate().toString(Qt::ISODate), comparedBy);
    for (const std::string& line : diff.lines())
        review.changes << QString::fromStdString(line);
    const ladder::ProjectLadder oldLadder(before.project, before.places);
    const ladder::ProjectLadder newLadder(after.project, after.places);
    for (const auto& network : diff.networks)
        review.networks.push_back(
            {QString::fromStdString(network.describe()),
             network.oldNumber ? oldLadder.layout(network.step, network.oldNumber) : std::nullopt,
             network.change == review::Pairing::Removed
                 ? std::nullopt
                 : newLadder.layout(network.step, network.number)});
    return review;
}

} // namespace rs::render
