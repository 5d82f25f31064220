// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "blockdoc/StateMachineTable.h"
#include "blockdoc/TimingExample.h"
#include "blocks/LibrarySearch.h"
#endif

#include <QCoreApplication>
#include <QString>
#include <QUrl>

namespace rs::ui {

// A block's documentation page as rich text, made from the library: what
// the block is, its pins and defaults, the timing diagram of its example,
// and for a state machine the states with their meaning and outputs and the
// transitions in the order they are tried.
class BlockDocumentation {
    Q_DECLARE_TR_FUNCTIONS(BlockDocumentation)
public:
    // The name the page's timing diagram is looked up by (an image resource
    // of the document that shows the page).
    static QUrl timingDiagramUrl();

    static QString html(const blocks::LoadedLibrary& library, const blocks::BlockDefinition& block,
                        const blockdoc::TimingExample& example);

private:
    static QString pinsTable(const blocks::BlockDefinition& block);
    static QString timingSection(const blocks::LoadedLibrary& library,
                                 const blocks::BlockDefinition& block,
                                 const blockdoc::TimingExample& example);
    static QString statesTable(const blocks::BlockDefinition& block,
                               const blockdoc::StateMachineTable& table);
    static QString transitionsTable(const blockdoc::StateMachineTable& table);
};

} // namespace rs::ui
