// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ladder/Layout.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

// A review of a change as pages a reviewer can print and sign: a first page
// with the projects, their signatures and the verdict and fields to sign,
// then each changed network, the old one beside the new one, the elements
// that differ marked. What the pages say; ReviewPdf draws them.
namespace rs::render {

struct ReviewNetwork {
    QString heading;                             // "Pluto 00 S0.0_0 network 4: changed"
    std::optional<ladder::NetworkLayout> before; // none: added
    std::optional<ladder::NetworkLayout> after;  // none: removed
};

struct Review {
    QString title;       // "Review of press-line.sps"
    QStringList summary; // the first page's lines: files, signatures, date, verdict
    QStringList changes; // every line of the diff
    std::vector<ReviewNetwork> networks;
};

} // namespace rs::render
