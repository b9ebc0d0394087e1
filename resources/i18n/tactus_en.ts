<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>tactus::gui::BookProgress</name>
    <message numerus="yes">
        <location filename="../../widgets/book_progress.cpp" line="92"/>
        <source>%n volume(s)</source>
        <translation>
            <numerusform>%n volume</numerusform>
            <numerusform>%n volumes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/book_progress.cpp" line="93"/>
        <source>%n sheet(s)</source>
        <translation>
            <numerusform>%n sheet</numerusform>
            <numerusform>%n sheets</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::EmbossChoice</name>
    <message numerus="yes">
        <location filename="../../widgets/emboss_choice.cpp" line="126"/>
        <source>Whole document: %n sheet(s)</source>
        <translation>
            <numerusform>Whole document: %n sheet</numerusform>
            <numerusform>Whole document: %n sheets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/emboss_choice.cpp" line="128"/>
        <source>Volume %1 of %2: %n sheet(s)</source>
        <translation>
            <numerusform>Volume %1 of %2: %n sheet</numerusform>
            <numerusform>Volume %1 of %2: %n sheets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/emboss_choice.cpp" line="133"/>
        <source>Pages %1 to %2: %n sheet(s)</source>
        <translation>
            <numerusform>Pages %1 to %2: %n sheet</numerusform>
            <numerusform>Pages %1 to %2: %n sheets</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::FindReplaceDialog</name>
    <message numerus="yes">
        <location filename="../../widgets/find_replace.cpp" line="118"/>
        <source>%n replaced</source>
        <translation>
            <numerusform>%n replaced</numerusform>
            <numerusform>%n replaced</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::GraphicView</name>
    <message numerus="yes">
        <location filename="../../widgets/document_loader.cpp" line="148"/>
        <source>%n dot(s).</source>
        <comment>on all the graphic&apos;s pages</comment>
        <translation>
            <numerusform>%n dot.</numerusform>
            <numerusform>%n dots.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::MainWindow</name>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="704"/>
        <source>Opened %1: %n sheet(s)</source>
        <translation>
            <numerusform>Opened %1: %n sheet</numerusform>
            <numerusform>Opened %1: %n sheets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="719"/>
        <source>%n line(s) could not be translated; they are left out of the braille</source>
        <translation>
            <numerusform>%n line could not be translated; it is left out of the braille</numerusform>
            <numerusform>%n lines could not be translated; they are left out of the braille</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="746"/>
        <source>Graphic %1 | %n sheet(s)</source>
        <translation>
            <numerusform>Graphic %1 | %n sheet</numerusform>
            <numerusform>Graphic %1 | %n sheets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="885"/>
        <source>with %n picture file(s) beside it</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="926"/>
        <source>Exported %1 (%n sheet(s))</source>
        <translation>
            <numerusform>Exported %1 (%n sheet)</numerusform>
            <numerusform>Exported %1 (%n sheets)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="1089"/>
        <source>%1 cannot keep %n of the document&apos;s pictures. Save anyway?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="1098"/>
        <source>Not saved: %1 cannot keep %n picture(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="1392"/>
        <source>Book settings: about %n sheet(s) per volume</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::PrinterPanel</name>
    <message numerus="yes">
        <location filename="../../widgets/printer_panel_queues.cpp" line="85"/>
        <source>%n Tactus queue(s) found on CUPS servers</source>
        <translation>
            <numerusform>%n Tactus queue found on CUPS servers</numerusform>
            <numerusform>%n Tactus queues found on CUPS servers</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/printer_panel_queues.cpp" line="189"/>
        <source>%1: %n sheet(s) embossed</source>
        <translation>
            <numerusform>%1: %n sheet embossed</numerusform>
            <numerusform>%1: %n sheets embossed</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::ProfileEditor</name>
    <message numerus="yes">
        <location filename="../../widgets/profile_editor.cpp" line="55"/>
        <source>%n cell(s) need %1 but the paper leaves %2 between the margins</source>
        <translation>
            <numerusform>%n cell needs %1 but the paper leaves %2 between the margins</numerusform>
            <numerusform>%n cells need %1 but the paper leaves %2 between the margins</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/profile_editor.cpp" line="57"/>
        <source>%n line(s) need %1 but the paper leaves %2 between the margins</source>
        <translation>
            <numerusform>%n line needs %1 but the paper leaves %2 between the margins</numerusform>
            <numerusform>%n lines need %1 but the paper leaves %2 between the margins</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::SheetPreview</name>
    <message numerus="yes">
        <location filename="../../widgets/sheet_preview.cpp" line="251"/>
        <source>Graphic: %n dot(s).</source>
        <translation>
            <numerusform>Graphic: %n dot.</numerusform>
            <numerusform>Graphic: %n dots.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/sheet_preview.cpp" line="284"/>
        <source>; %n front and back dots too close</source>
        <translation>
            <numerusform>; %n front and back dot too close</numerusform>
            <numerusform>; %n front and back dots too close</numerusform>
        </translation>
    </message>
</context>
</TS>
