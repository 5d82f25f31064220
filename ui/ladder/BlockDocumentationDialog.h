// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "blocks/LibrarySearch.h"
#endif

#include <QDialog>

class QTextBrowser;

namespace rs::ui {

// A block's documentation page (BlockDocumentation) in a window of its own,
// its timing diagram drawn from the block's example in the window's colours.
// It copies the block, so it may outlive the libraries it was opened from.
class BlockDocumentationDialog : public QDialog {
    Q_OBJECT
public:
    BlockDocumentationDialog(const blocks::LoadedLibrary& library,
                             const blocks::BlockDefinition& block, QWidget* parent = nullptr);

    // Opens the page as a window beside `parent` that closes itself.
    static void show(const blocks::LoadedLibrary& library, const blocks::BlockDefinition& block,
                     QWidget* parent);

    QTextBrowser* page() const { return m_page; }

private:
    QTextBrowser* m_page;
};

} // namespace rs::ui
