<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
    <context>
        <name>stylos::app::CommandLine</name>
        <message>
            <source>Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene.</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Wait until loading ends, save the window as a PNG image to &lt;file&gt; and exit (status 1 if a file could not be loaded).</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>file</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Point files to load (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ).</source>
            <translation type="unfinished" />
        </message>
    </context>
    <context>
        <name>stylos::app::MainActions</name>
        <message>
            <source>&amp;File</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>&amp;Help</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>&amp;Open scans…</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Load point files (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ) into the scene</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Open &amp;demo</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Replace the scene by the demo scene: a fluted drum, two fragments and an omphalos</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>&amp;About Stylos</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Point files (*.ply *.las *.xyz *.asc *.csv *.pts *.txt *.obj)</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>All files (*)</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Open scans</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>About Stylos</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;A workbench for very large 3D scans of monuments: column drums, capitals, fragments.&lt;/p&gt;&lt;p&gt;Point-based, after Duguet, Drettakis, Girardeau-Montaut, Martinez and Schneider (VAST 2004).&lt;/p&gt;</source>
            <translation type="unfinished" />
        </message>
    </context>
    <context>
        <name>stylos::app::MainWindow</name>
        <message>
            <source>Stylos</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Cancelled</source>
            <translation type="unfinished" />
        </message>
        <message numerus="yes">
            <source>%n file(s) in the scene</source>
            <translation>
                <numerusform>%n file in the scene</numerusform>
                <numerusform>%n files in the scene</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n problem(s) while loading:</source>
            <translation>
                <numerusform>%n problem while loading:</numerusform>
                <numerusform>%n problems while loading:</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::DemoScene</name>
        <message>
            <source>Could not create the demo folder %1.</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Generating the demo scene</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Could not generate the demo scene: %1.</source>
            <translation type="unfinished" />
        </message>
    </context>
    <context>
        <name>stylos::widgets::ErrorText</name>
        <message>
            <source>Could not load %1: %2.</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the file does not exist</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the file cannot be read</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the file format is not recognised</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>this format is not supported</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the file is malformed</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the file is truncated</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the file is empty</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>the output could not be written</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>a parameter is out of range</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>not enough memory for this operation</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>cancelled</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>unknown error</source>
            <translation type="unfinished" />
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneLoader</name>
        <message numerus="yes">
            <source>Loading %n file(s)</source>
            <translation>
                <numerusform>Loading %n file</numerusform>
                <numerusform>Loading %n files</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneSummaryModel</name>
        <message>
            <source>min (%1, %2, %3)
max (%4, %5, %6)</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>none</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>File</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Format</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Points</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Skipped</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Size (x × y × z)</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Attributes</source>
            <translation type="unfinished" />
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneSummaryWidget</name>
        <message>
            <source>No scan loaded</source>
            <translation type="unfinished" />
        </message>
        <message numerus="yes">
            <source>Total: %1 points in %n file(s)</source>
            <translation>
                <numerusform>Total: %1 points in %n file</numerusform>
                <numerusform>Total: %1 points in %n files</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::TaskStatusWidget</name>
        <message>
            <source>Cancel</source>
            <translation type="unfinished" />
        </message>
        <message>
            <source>Stop the running task</source>
            <translation type="unfinished" />
        </message>
    </context>
</TS>
