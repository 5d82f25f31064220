// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointer>

namespace rs::ui {

class ProjectDocument;

// Which page the window shows: a node of the project tree.
struct PageRef {
    // Code is the unit's code as text; Ladder the same code as ladder networks.
    enum class Kind {
        None,
        Project,
        ProjectText,
        Unit,
        IoOptions,
        AsiOptions,
        Gateway, // station: the gateway's node address
        Variables,
        Code,
        Ladder,
        Properties // the project's properties (.prop) and their proofs
    };

    Kind kind = Kind::None;
    QPointer<ProjectDocument> document;
    int station = -1;
    int sequence = 0; // Code, Ladder: 0 is the unit's PLC code, 1-9 its sequences

    bool operator==(const PageRef& other) const;
};

} // namespace rs::ui
