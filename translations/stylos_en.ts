<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>QAbstractFileIconProvider</name>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder</source>
        <comment>All other platforms</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shortcut</source>
        <comment>All other platforms</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Look in:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go to the parent directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create a New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>List View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change to list view mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change to detail view mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sidebar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>List of places and bookmarks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Choose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All Files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Directory:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Directories</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find Directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Rename</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show &amp;hidden files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recent Places</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
File not found.
Please verify the correct file name was given.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
Directory not found.
Please verify the correct directory name was given.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is write protected.
Do you want to delete it anyway?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not delete directory.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invalid filename</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::AnnotationActions</name>
    <message>
        <source>The legend has no class in this layer: add one first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Erase with the lasso</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lasso in 3D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lasso: no fragment selected or under the lasso</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lasso: no visible cell changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Annotate in 3D (&amp;lasso)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw a lasso in the 3D view: the visible cells of the selected fragment inside it take the chosen class; Ctrl erases; Escape cancels; Alt-drag orbits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Erase with the lasso</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The lasso removes the class of the cells it takes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The class the lasso gives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Material / condition layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tool mark layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D lasso</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Erase</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lasso: the selected fragment is hidden; show it to annotate it in 3D</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::AssemblyActions</name>
    <message>
        <source>Assembly %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %n fragment(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>New &amp;assembly from selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group the selected fragments into an assembly that moves as one; a drum among them (a fragment with an axis guide) becomes what they dock against</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Take out of assembly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the selected fragments back to the top of the scene, where they are</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove assembly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dissolve the selected assembly; its fragments stay where they are</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Use as the assembly&apos;s drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dock the assembly&apos;s fragments against the guides of the selected fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dé&amp;veloppée of the assembly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unroll the assembly&apos;s drum with every fragment of the assembly at its place, on the drum&apos;s axis: the reconstruction in 2D, the free places; click a fragment to select it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::Automation</name>
    <message>
        <source>Demo drum (%1): A, développée under the skydome, material and condition in colour; B, front view lit from the viewer, the same classes as black-and-white hatches. Generated scan; the painted regions are an illustration.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::CommandLine</name>
    <message>
        <source>Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wait until the scene and its tasks are ready and the view is refined, save the window as a PNG image to &lt;file&gt; and exit (status 1 if something failed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Orbit the camera for &lt;frames&gt; frames at 1280 × 800 once the scene is ready, print the frame times as JSON and exit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A project (.stylos), or scans to import (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--orbit-benchmark: &apos;%1&apos; is not a frame count (1 to 100000)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--orbit-benchmark needs exactly one file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--grab and --orbit-benchmark do not go together</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn the first fragment, a change of its pose every frame, for &lt;frames&gt; frames at 1280 × 800 once the scene is ready, print the frame times as JSON and exit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--pose-benchmark: &apos;%1&apos; is not a frame count (1 to 100000)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--pose-benchmark needs exactly one file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--pose-benchmark goes with neither --grab nor --orbit-benchmark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --grab: first fit the first fragment&apos;s drum guides, dock against it and show the Move tool on the second fragment, in the drum&apos;s frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--gizmo goes with --grab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --grab: first fit the first fragment&apos;s drum guides, dock the second fragment to its flutes from where it stands and show its contact readout.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--dock goes with --grab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--dock and --gizmo do not go together</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --grab: first label three regions of the first fragment with the 3D lasso (preserved marble, fractured marble, plaster) and show the Annotation shading.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--annotation goes with --grab alone</source>
        <translation></translation>
    </message>
    <message>
        <source>--paint goes with --grab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --grab: paint as --paint, then write the first fragment&apos;s plate (its développée and front view at 1:N) to BASE.pdf and BASE.png, and grab the Export plate dialog.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--plate goes with --grab alone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --grab: first compute the first fragment&apos;s développée and paint a few annotation regions on it (marble, fractured marble, plaster; a claw-chisel area in the tool-mark layer). With --dock too: after the dock, the développée of the second fragment&apos;s assembly, painted across the drum and the fragment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--paint does not go with --gizmo or --annotation</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::DeveloppeeDock</name>
    <message>
        <source>Développée</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::DeveloppeeLink</name>
    <message>
        <source>Développée of %1 cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The développée of %1 needs a drum with an axis guide (Use as the assembly&apos;s drum)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The développée of %1 cannot start: its drum is still opening or busy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Développée of %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is unrolled about its drum&apos;s axis guide and does not stand on the drum yet: dock it first, or untick Use the axis guide to unroll it about a cylinder fitted to itself.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::DisplaySettingsWidget</name>
    <message>
        <source>Headlight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> M points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points drawn at most; the view refines up to it when the camera stops</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>View-dependent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Global level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Splat size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point budget</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Level of detail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size of the drawn points, as a multiple of the size of their octree cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>View-dependent: finer cells near the camera, within the point budget; global level: every fragment drawn at the one octree level below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The octree level drawn when the level of detail is global (0: the root cell)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Octree level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eye-dome lighting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Annotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The layer the Annotation shading shows and the 3D lasso labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Annotation layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How the points are lit: by a light at the eye (headlight), by the sky each cell sees (skydome; needs Tools › Compute skydome, else the headlight), in the scan&apos;s colours, by eye-dome lighting (the relief from the depth alone), or tinted by each cell&apos;s class in the annotation layer below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the small gaps between the drawn points on screen, and hide a far surface seen through a narrow gap in a nearer one, when the view stops; openings of the scan wider than the points stay open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fill gaps</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::DockingActions</name>
    <message>
        <source>Docking against %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The guides of this fragment are being fitted already, or its octree is not open yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Guides of %1: %2 flutes, leading radius %3 mm, flute depth %4 mm, RMS %5 mm, %6 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Move tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the selected fragment with arrows and rings in the 3D view; Shift: finer, Ctrl: by degrees, Alt: tilts, L: the next frame, Escape: cancel the drag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gizmo &amp;frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;World</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dock against this &amp;drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the axis and flutes of the selected fragment for the gizmo&apos;s Drum frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit drum &amp;guides</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the axis and the flute lines of the selected drum in the background</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>De&amp;lete guides</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the axis and flute guides of the selected fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show &amp;guides</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This fragment is being docked already, or its octree or the drum&apos;s is not open yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dock to &amp;flutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Snap the selected fragment onto the nearest flutes of the docking drum and refine its pose against them (one undo step)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Docking &amp;locks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock &amp;z (along the axis)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock &amp;r (radial)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock &amp;θ (about the axis)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock &amp;tilts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set &amp;axis from two points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click two points on the selected fragment in the 3D view: its axis guide goes through them (Escape cancels)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit axis…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type the point and direction of the selected fragment&apos;s axis guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reverse axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn the selected fragment&apos;s axis guide end for end: a drum lying on its side whose développée came out upside down unrolls the right way up</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::LegendDock</name>
    <message>
        <source>Legend</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::LogDock</name>
    <message>
        <source>Log</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::MainActions</name>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;demo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Stylos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Stylos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;A workbench for very large 3D scans of monuments: column drums, capitals, fragments.&lt;/p&gt;&lt;p&gt;Point-based, after Duguet, Drettakis, Girardeau-Montaut, Martinez and Schneider (VAST 2004).&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standard &amp;views</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo the last change to the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo the change undone last</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove from the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fit to the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit to the &amp;selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Headlight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;kydome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan &amp;colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute &amp;skydome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute the 3D skydome (ambient occlusion) of the selected fragments in the background; the view then shades them by it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Développée</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unroll the selected fragment in the Développée dock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the demo scene: a fluted drum, two of its fragments and an omphalos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Eye-dome lighting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Annotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Orthographic</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Développée</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::MainWindow</name>
    <message>
        <source>Stylos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Remove %n fragment(s)</source>
        <translation>
            <numerusform>Remove %n fragment</numerusform>
            <numerusform>Remove %n fragments</numerusform>
        </translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n scan(s) could not be imported:</source>
        <translation>
            <numerusform>%n scan could not be imported:</numerusform>
            <numerusform>%n scans could not be imported:</numerusform>
        </translation>
    </message>
    <message>
        <source>The skydome of the selection is being computed already, or its octrees are not open yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1[*] — Stylos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3 (core profile), which this display does not offer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome of %1: %2 cells at level %3, %4 sky directions, %5 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>View and tools toolbar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not compute the skydome of %1: its octree %2 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::PlateActions</name>
    <message>
        <source>Export &amp;plate…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A publication plate at an exact scale: développées and orthographic views at 1:N with scale bars, legend and caption, as PDF, SVG, TIFF or PNG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;développée image…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The développée on show as PNG or TIFF with its pixel size, and its map (.json) beside it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export plate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF (*.pdf);;SVG (*.svg);;TIFF (*.tif *.tiff);;PNG (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing the plate %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing the plate was cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote the plate %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not draw the plate: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no développée to export: compute one first (Tools › Développée)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export développée image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG (*.png);;TIFF (*.tif *.tiff)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export the développée: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not write the développée&apos;s map: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote the développée %1 and its map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;view image…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The visible fragments seen along the 3D view&apos;s direction, orthographic, every cell drawn, at a width you choose, as PNG or TIFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export view image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no 3D view to export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rendering the view %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote the view image %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Width in pixels (the whole image at most %L1 million pixels)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rendering the view image %1 was cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not render the view image %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::ProjectActions</name>
    <message>
        <source>&amp;New project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a Stylos project (.stylos)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import scans…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Build a packed octree of each scan in the background and add it to the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a project opens alone, not with other files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stylos projects (*.stylos)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stylos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project %1 has unsaved changes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import scans</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No recent project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The project uses %n octree(s) outside its folder, %1 in all.</source>
        <translation>
            <numerusform>The project uses %n octree outside its folder, %1 in all.</numerusform>
            <numerusform>The project uses %n octrees outside its folder, %1 in all.</numerusform>
        </translation>
    </message>
    <message>
        <source>Copied into the folder, they travel with it: the folder can be moved or copied whole. Left where they are, the project names them there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy into the folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leave them where they are</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Saved %1, with %n octree(s) copied into its folder</source>
        <translation>
            <numerusform>Saved %1, with %n octree copied into its folder</numerusform>
            <numerusform>Saved %1, with %n octrees copied into its folder</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Removed %n unused octree(s) from the cache, %1 freed</source>
        <translation>
            <numerusform>Removed %n unused octree from the cache, %1 freed</numerusform>
            <numerusform>Removed %n unused octrees from the cache, %1 freed</numerusform>
        </translation>
    </message>
    <message>
        <source>Open</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import</source>
        <comment>toolbar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The demo is rebuilt when it is opened again: save your work as a project of your own.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save %1: it is in the demo&apos;s folder, rebuilt when the demo is opened again. Choose another folder.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::PropertiesDock</name>
    <message>
        <source>Properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Display</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact with the drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Placement in the drum frame</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::StatusReadout</name>
    <message>
        <source>x %1  y %2  z %3 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 fps · %2 ms · %3 M points</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::app::TasksDock</name>
    <message>
        <source>Tasks</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AddFragmentCommand</name>
    <message>
        <source>Add %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AssemblyDeveloppeeJob</name>
    <message>
        <source>Développée of %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AxisGuideEditor</name>
    <message>
        <source>Set axis cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click two points on %1 for its axis (Escape cancels)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The two points picked on %1 are the same: pick two points apart along its axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the axis of %1 from two points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis of %1 set through the two points picked, %2 mm apart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit the axis of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reverse the axis of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis of %1 now points the other way: its développée turns upside down</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ClassMeasures</name>
    <message>
        <source>Areas of the classes of %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ContactJob</name>
    <message>
        <source>Contact of %1 with the drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not measure the contact of %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ContactReadoutWidget</name>
    <message>
        <source>Largest interpenetration:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Median gap:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gap, 90 % of points:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gap, 99 % of points:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Within 0.5 mm:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points measured:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signed distance of the fragment&apos;s outer face to the drum&apos;s flute profile, along its normal; negative: inside the drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set a docking drum with guides (Tools › Dock against this drum) and select another fragment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Against the docking drum&apos;s flute profile:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The fragment does not touch the drum (no point of it within 5 mm of the profile).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Against %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Against %1: no contact (no point within 5 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Against %1: largest interpenetration %2, median gap %3, 90 % gap %4 (%5 points)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DemoScene</name>
    <message>
        <source>Could not create the demo folder %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fragment A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fragment B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Omphalos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preparing the demo scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not prepare the demo scene: %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drum 1 reconstruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flute %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeAnnotator</name>
    <message>
        <source>Erase %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not painted: the développée of the assembly is out of date (%1). Compute it again to paint.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its drum was removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a fragment was removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is no longer in the assembly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” was moved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the octree of “%1” changed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeJob</name>
    <message>
        <source>Développée of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not compute the développée of %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeePanel</name>
    <message>
        <source>%1: %2, radius %3 mm, RMS %4 mm, %5 % inliers; %6 × %7 pixels of %8 mm; %9 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pixel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The surface the développée is unrolled from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How the heights become grey: the sky each point sees, one light, or height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Side of a pixel; Automatic uses the octree&apos;s leaf size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the axis guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit only the radius about the fragment&apos;s axis guide (needed for a fragment)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the développée to the view (F)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute the développée of the selected fragment in the background</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No développée yet: select a fragment and press Compute.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing the développée of %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a fragment to compute its développée.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Press Compute for the développée of %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Horizon directions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome shading of the développée: how many azimuths each pixel searches for its horizon (more is smoother and slower). Not the 3D view&apos;s skydome.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>noise %1 mm smoothed by %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>noise %1 mm, raw heights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smooth noise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome: smooth the scanner&apos;s noise out of the heights before the horizon search, so that flat, open surfaces read evenly instead of as salt and pepper. Off: the raw heights.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Width (Gaussian σ) of the smoothing; Automatic sets it from the noise measured on the heights. The status line says what was used.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; </source>
        <comment>between the parts of a status line</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeSettings</name>
    <message>
        <source>the number of directions must be between %1 and %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the pixel size must be a positive length, or 0 for automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the light elevation must be between 0° and 90°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the axis needs a finite point and a non-zero direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface of revolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the unrolling radius must be a positive length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the smoothing must be a positive length, or 0 for automatic</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeView</name>
    <message>
        <source>No développée yet: select a fragment and press Compute.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>u %1 mm   v %2 mm   (no data)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>u %1 mm   v %2 mm   h %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DockJob</name>
    <message>
        <source>Dock %1 to the flutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>θ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>r</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tangent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>roll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ±%2°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ±%2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Docked %1: RMS %2 mm over %3 points, moved %4 flutes about the axis, %5 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uncertainty %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not fixed by the flutes, left as it was: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; </source>
        <comment>between the parts of a status line</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: its %2 points are too few (at least 200 are needed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: it is too far from the drum; %2 of its points lie within %3 mm of the drum&apos;s surface (at least 200 are needed). Bring it nearer its place on the drum (the Move tool, or its placement in the drum frame in Properties) and dock again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: from where it stands its outer face does not meet the drum&apos;s surface. Bring it nearer its place on the drum and dock again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: no flutes can be read on its outer face (flute signal %2, at least %3 needed). Lock θ (Tools › Docking locks) to dock it against the drum&apos;s surface alone.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: fewer than 200 of its points stayed on the flutes. Start it nearer its place and dock again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: the registration did not settle in %2 iterations.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 times the drum&apos;s own RMS: it may rest on the wrong flute or be held off its place by a lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not dock %1: the registration did not settle in %2 iterations. θ is locked and may hold it off its flute: unlock θ (Tools › Docking locks), or bring it onto its flute first.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DockRunner</name>
    <message>
        <source>The docking drum changed while its guides were fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 or the drum moved while it was docked: the dock was not applied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dock %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Docking %1 was cancelled</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DrumFramePoseWidget</name>
    <message>
        <source>θ about the axis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z along the axis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>r from the axis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lean:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Roll:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Azimuth of the fragment&apos;s centre about the drum axis, from the drum&apos;s reference direction (as in its développée); typing turns the fragment about the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Height of the fragment&apos;s centre along the drum axis, from the axis guide&apos;s point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distance of the fragment&apos;s centre from the drum axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn about the tangent through the fragment&apos;s centre (leans it in or out)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn about the radial direction through the fragment&apos;s centre (turns its flutes sideways)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This fragment has no drum with an axis guide (put it in an assembly with a drum, or Tools › Dock against this drum), or its octree is not open yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No fragment selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In the frame of %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spin:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn about the line through the fragment&apos;s centre parallel to the axis; with θ and the tilts it fixes the orientation. The tilts and the spin are measured from the fragment&apos;s frame as scanned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This is the drum the others are placed against: select one of them.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::EditAxisDialog</name>
    <message>
        <source>Edit axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The axis guide in the fragment&apos;s own frame: a point on it and its direction.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point (x, y, z):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction (x, y, z):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The direction of the axis cannot be zero: give at least one non-zero component (for a vertical axis: 0, 0, 1).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ErrorText</name>
    <message>
        <source>Could not load %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file format is not recognised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this format is not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is malformed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is truncated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the output could not be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not enough memory for this operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>these data and settings do not allow it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::FragmentPropertiesWidget</name>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Visible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotation X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotation Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotation Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leaf cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Total cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shown in the 3D view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the fragment&apos;s display colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Translation along the scene&apos;s x axis, in metres</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotation about the x axis, applied first, in degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>opening…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fragment colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Imported as</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 up, in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offset %1, %2, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Extent of the fragment&apos;s leaf cells along its own x, y and z axes (its scan&apos;s frame, z up), whatever its pose</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GizmoReadout</name>
    <message>
        <source>Along the fragment&apos;s X: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along X: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along the fragment&apos;s Y: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along Y: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along the fragment&apos;s Z: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along Z: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About the fragment&apos;s X: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About X: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About the fragment&apos;s Y: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Y: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About the fragment&apos;s Z: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Z: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along the drum axis: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radially: %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tilt about the radial direction: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tilt about the tangent: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>About the drum axis: %1° (%n flute(s))</source>
        <translation>
            <numerusform>About the drum axis: %1° (%n flute)</numerusform>
            <numerusform>About the drum axis: %1° (%n flutes)</numerusform>
        </translation>
    </message>
    <message>
        <source>About the drum axis: %1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 · Esc cancels</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GuideFitJob</name>
    <message>
        <source>Drum guides of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not fit the guides of %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flute %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GuideFitRunner</name>
    <message>
        <source>Delete the guides of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the guides of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fitting the guides of %1 was cancelled</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ImportOptionsDialog</name>
    <message>
        <source>Import options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stylos works with Z up and in metres. Say how the scans are stored: their points are turned and scaled once, as their octrees are built, and the project remembers it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Up axis of the scans:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Unit of the scans:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>+Z (already upright)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>−Z (upside down)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>+Y (Y up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>−Y (Y down)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>+X (X up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>−X (X down)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>metres (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centimetres (cm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Offset (site coordinates, in that unit):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subtracted from every x, before the turn and the scaling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subtracted from every y, before the turn and the scaling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subtracted from every z, before the turn and the scaling</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::LegendText</name>
    <message>
        <source>preserved marble</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fractured marble</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>plaster/restoration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flat chisel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>claw chisel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>drill</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rasp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagonal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back diagonal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cross</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagonal cross</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Horizontal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Solid</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::LegendWidget</name>
    <message>
        <source>Colour of “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename class “%1” to “%2”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recolour class “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the hatch of “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>class %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add class “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete class “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s) hold this class. What becomes of them?</source>
        <translation>
            <numerusform>%Ln cell holds this class. What becomes of it?</numerusform>
            <numerusform>%Ln cells hold this class. What becomes of them?</numerusform>
        </translation>
    </message>
    <message>
        <source>Unlabel them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move them to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The black-and-white pattern of this class on plates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Being measured…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface area on the object, m²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Class</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area (m²)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a class to the layer of the selected row</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the colour of the selected class</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected class (its cells are unlabelled or moved to another class)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click a class to paint it; double-click its name to rename it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PaintToolBar</name>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Navigate: drag to pan, click to mark the point in 3D (N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brush</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint the active class with a round brush (B)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eraser</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unlabel the cells under a round brush (E)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fill a polygon with the active class: click its corners and double-click, or drag a lasso (L); Escape cancels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fill the connected pixels of similar height or shading with the active class (W)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Holes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fill the holes enclosed by the clicked region with its class (H)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The annotation layer shown and painted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The class the brush, polygon and wand paint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brush and eraser diameter on the object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the magic wand compares</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The magic wand takes pixels within this of the clicked one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opacity of the annotation over the développée</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PlateDialog</name>
    <message>
        <source>Développée</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Headlight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Margins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resolution (dpi)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bits per sample (TIFF, PNG)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Template</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Caption</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Panels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export plate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Legend of the annotation classes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scale 1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Annotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hatches</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a template…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Développée and front view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Front, right and top views</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(all visible; the first for a développée)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing the preview…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turned (%1 × %2 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A4 (210 × 297 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A3 (297 × 420 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>US letter (215.9 × 279.4 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Journal print area, 170 × 105 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Journal print area, 205 × 135 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 × %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Panel %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The panel (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2; the print area is %3: use %4 or smaller, or a larger page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2; the print area is %3: no scale fits this page, use a larger page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, placed at (%2, %3) mm, is %4 with its texts and leaves the %5 page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The plate needs %1 mm of height; the print area is %2: use smaller scales, a larger page or the other orientation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The plate needs %1 mm of height; the print area is %2: use smaller scales (%3), a larger page or the other orientation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The caption needs %1 mm of height on its own; the print area is %2: shorten the caption or use a larger page.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PlateTexts</name>
    <message>
        <source>développée</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>front view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>back view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>top view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bottom view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>orthographic view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>skydome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>headlight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>.</source>
        <comment>the decimal point of the numbers on a plate</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::RemoveFragmentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::RenameFragmentCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ScanImporter</name>
    <message>
        <source>Scans and octrees (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Packed octrees (*.poct)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not import %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln point(s) with NaN or infinite coordinates skipped</source>
        <translation>
            <numerusform>%1: %Ln point with NaN or infinite coordinates skipped</numerusform>
            <numerusform>%1: %Ln points with NaN or infinite coordinates skipped</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not import %1: the folder %2 cannot be created or written to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 holds %Ln scan(s), merged into one fragment; each point&apos;s normal was estimated from its own scan&apos;s points</source>
        <translation>
            <numerusform>%1 holds %Ln scan, merged into one fragment; each point&apos;s normal was estimated from its own scan&apos;s points</numerusform>
            <numerusform>%1 holds %Ln scans, merged into one fragment; each point&apos;s normal was estimated from its own scan&apos;s points</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SceneDocument</name>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project has no file yet: choose one with Save as.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New assembly %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove assembly %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take out of assembly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move into %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the drum of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the legend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the class %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save the annotations of %1 into %2: %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the plate&apos;s settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not copy the octrees into the project&apos;s folder: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The plate layout kept in %1 could not be read: the project opens without it, and its text stays in the file until a new plate is set (File › Export plate…).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds keys this version of Stylos does not read; they are left out and will not be saved: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SceneTreeModel</name>
    <message>
        <source>%1 (missing)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Groove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Développée (%1, %2 × %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Assembly of %n fragment(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Docks against %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentColourCommand</name>
    <message>
        <source>Change the colour of %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentGuidesCommand</name>
    <message>
        <source>Change the guides of %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentPoseCommand</name>
    <message>
        <source>Move %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentVisibleCommand</name>
    <message>
        <source>Show %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SkydomeJob</name>
    <message>
        <source>Skydome of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not compute the skydome of %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::TaskListWidget</name>
    <message>
        <source>No background tasks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop this task</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ViewportWidget</name>
    <message>
        <source>The 3D view needs OpenGL 3.3: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
