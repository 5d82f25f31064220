// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "blocks/LibrarySearch.h"
#endif

#include <QDialog>

#include <utility>
#include <vector>

class QLineEdit;
class QListWidget;
class QTextBrowser;

namespace rs::ui {

// Chooses a block of the project's libraries to insert (New Network →
// Function…): the list narrows to the blocks whose name or description
// holds what is typed, and the chosen block's description and pins are
// shown beside it.
class BlockChooserDialog : public QDialog {
    Q_OBJECT
public:
    BlockChooserDialog(const blocks::LibrarySet& libraries, QWidget* parent = nullptr);

    // The chosen block once accepted; null before.
    const blocks::LoadedLibrary* library() const;
    const blocks::BlockDefinition* block() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void filter();
    void showChosen();
    void showDocumentation();

    std::vector<std::pair<const blocks::LoadedLibrary*, const blocks::BlockDefinition*>> m_blocks;
    QLineEdit* m_filter;
    QListWidget* m_list;
    QTextBrowser* m_description;
};

} // namespace rs::ui
