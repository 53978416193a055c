#include "edit_primitive_factory.h"

#include "edit_primitive.h"

// A shortcut makes the tool reachable without finding its toolbar button (and scriptable in GUI tests).
EditPrimitiveFactory::EditPrimitiveFactory()
    : EditPluginAdapter("EditPrimitive", QIcon(":/edit_primitive/images/edit_primitive.png"), "Primitive Edit",
                        "Primitive Edit: pick, merge and split segments, fit primitives, edit their parameters and "
                        "snap segments onto them (Ctrl+Shift+P)",
                        QKeySequence(Qt::CTRL + Qt::SHIFT + Qt::Key_P))
{
}

primitive_edit::meshlab::EditToolAdapter* EditPrimitiveFactory::createTool() { return new EditPrimitivePlugin(); }

QString EditPrimitiveFactory::description() const { return EditPrimitivePlugin::Info(); }
