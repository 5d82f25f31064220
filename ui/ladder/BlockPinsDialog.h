// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "blocks/BlockInstance.h"
#include "blocks/BlockLibrary.h"
#endif

#include <QDialog>
#include <QPointer>

#include <optional>
#include <vector>

class QLabel;
class QLineEdit;

namespace rs::ui {

class ProjectDocument;

// Binds the pins of one block instance: a row per pin with its kind and
// default, a field with the same completion of the unit's names as an
// element's, and "???" shown for a pin left open. What it accepts expands
// in the unit (blocks::callProblems); otherwise it says why and stays open.
class BlockPinsDialog : public QDialog {
    Q_OBJECT
public:
    BlockPinsDialog(ProjectDocument* document, int station, const blocks::BlockDefinition& block,
                    const blocks::BlockInstance& instance, QWidget* parent = nullptr);

    // The instance with the pins as bound, once accepted.
    const std::optional<blocks::BlockInstance>& instance() const { return m_result; }

    void accept() override;

private:
    QPointer<ProjectDocument> m_document;
    int m_station;
    blocks::BlockDefinition m_block;
    blocks::BlockInstance m_instance;
    std::vector<QLineEdit*> m_fields; // one per pin, in the block's order
    QLabel* m_problem;
    std::optional<blocks::BlockInstance> m_result;
};

} // namespace rs::ui
