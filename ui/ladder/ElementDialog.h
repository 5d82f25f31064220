// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ElementKind.h"

#include <QDialog>
#include <QPointer>

#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QLineEdit;

namespace rs::ui {

class ProjectDocument;

// The properties of one element or output (manual 11.2): its kind, its
// variable with completion of the unit's symbolic names, the value of a
// comparison or arithmetic box, a comment on an output, and "New Variable..."
// to name a variable on the spot (an undo step of its own). What it accepts is
// read by the language's own parser, so it is always one valid element.
class ElementDialog : public QDialog {
    Q_OBJECT
public:
    ElementDialog(ProjectDocument* document, int station, bool output, const ElementFields& fields,
                  QWidget* parent = nullptr);

    // Read when the dialog was accepted.
    const std::optional<ladder::Element>& element() const { return m_element; }
    const std::optional<ladder::Output>& output() const { return m_output; }

    void accept() override;

private:
    void kindChanged();
    void newVariable();
    void fillCompletion();

    QPointer<ProjectDocument> m_document;
    int m_station;
    bool m_isOutput;
    QComboBox* m_kind;
    QLabel* m_operandLabel;
    QPushButton* m_newVariable;
    QLineEdit* m_operand;
    QLabel* m_valueLabel;
    QLineEdit* m_value;
    QCheckBox* m_negated;
    QLineEdit* m_comment = nullptr;
    QLabel* m_problem;
    std::optional<ladder::Element> m_element;
    std::optional<ladder::Output> m_output;
};

} // namespace rs::ui
