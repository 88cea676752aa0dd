<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr">
    <context>
        <name>stylos::app::CommandLine</name>
        <message>
            <source>Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene.</source>
            <translation>Stylos, un atelier pour les très grands relevés 3D de monuments. Sans fichier, ouvre la scène de démonstration.</translation>
        </message>
        <message>
            <source>Wait until loading ends, save the window as a PNG image to &lt;file&gt; and exit (status 1 if a file could not be loaded).</source>
            <translation>Attendre la fin du chargement, enregistrer la fenêtre en image PNG dans &lt;fichier&gt; et quitter (code 1 si un fichier n’a pas pu être chargé).</translation>
        </message>
        <message>
            <source>file</source>
            <translation>fichier</translation>
        </message>
        <message>
            <source>Point files to load (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ).</source>
            <translation>Fichiers de points à charger (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ).</translation>
        </message>
    </context>
    <context>
        <name>stylos::app::MainActions</name>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Fichier</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>&amp;Aide</translation>
        </message>
        <message>
            <source>&amp;Open scans…</source>
            <translation>&amp;Ouvrir des relevés…</translation>
        </message>
        <message>
            <source>Load point files (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ) into the scene</source>
            <translation>Charger des fichiers de points (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ) dans la scène</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>&amp;Quitter</translation>
        </message>
        <message>
            <source>Open &amp;demo</source>
            <translation>Ouvrir la &amp;démonstration</translation>
        </message>
        <message>
            <source>Replace the scene by the demo scene: a fluted drum, two fragments and an omphalos</source>
            <translation>Remplacer la scène par la scène de démonstration : un tambour cannelé, deux fragments et un omphalos</translation>
        </message>
        <message>
            <source>&amp;About Stylos</source>
            <translation>À &amp;propos de Stylos</translation>
        </message>
        <message>
            <source>Point files (*.ply *.las *.xyz *.asc *.csv *.pts *.txt *.obj)</source>
            <translation>Fichiers de points (*.ply *.las *.xyz *.asc *.csv *.pts *.txt *.obj)</translation>
        </message>
        <message>
            <source>All files (*)</source>
            <translation>Tous les fichiers (*)</translation>
        </message>
        <message>
            <source>Open scans</source>
            <translation>Ouvrir des relevés</translation>
        </message>
        <message>
            <source>About Stylos</source>
            <translation>À propos de Stylos</translation>
        </message>
        <message>
            <source>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;A workbench for very large 3D scans of monuments: column drums, capitals, fragments.&lt;/p&gt;&lt;p&gt;Point-based, after Duguet, Drettakis, Girardeau-Montaut, Martinez and Schneider (VAST 2004).&lt;/p&gt;</source>
            <translation>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;Un atelier pour les très grands relevés 3D de monuments : tambours de colonne, chapiteaux, fragments.&lt;/p&gt;&lt;p&gt;Fondé sur les points, d’après Duguet, Drettakis, Girardeau-Montaut, Martinez et Schneider (VAST 2004).&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>stylos::app::MainWindow</name>
        <message>
            <source>Stylos</source>
            <translation>Stylos</translation>
        </message>
        <message>
            <source>Cancelled</source>
            <translation>Annulé</translation>
        </message>
        <message numerus="yes">
            <source>%n file(s) in the scene</source>
            <translation>
                <numerusform>%n fichier dans la scène</numerusform>
                <numerusform>%n fichiers dans la scène</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n problem(s) while loading:</source>
            <translation>
                <numerusform>%n problème lors du chargement :</numerusform>
                <numerusform>%n problèmes lors du chargement :</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::DemoScene</name>
        <message>
            <source>Could not create the demo folder %1.</source>
            <translation>Impossible de créer le dossier de démonstration %1.</translation>
        </message>
        <message>
            <source>Generating the demo scene</source>
            <translation>Génération de la scène de démonstration</translation>
        </message>
        <message>
            <source>Could not generate the demo scene: %1.</source>
            <translation>Impossible de générer la scène de démonstration : %1.</translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::ErrorText</name>
        <message>
            <source>Could not load %1: %2.</source>
            <translation>Impossible de charger %1 : %2.</translation>
        </message>
        <message>
            <source>the file does not exist</source>
            <translation>le fichier n’existe pas</translation>
        </message>
        <message>
            <source>the file cannot be read</source>
            <translation>le fichier ne peut pas être lu</translation>
        </message>
        <message>
            <source>the file format is not recognised</source>
            <translation>le format du fichier n’est pas reconnu</translation>
        </message>
        <message>
            <source>this format is not supported</source>
            <translation>ce format n’est pas pris en charge</translation>
        </message>
        <message>
            <source>the file is malformed</source>
            <translation>le fichier est mal formé</translation>
        </message>
        <message>
            <source>the file is truncated</source>
            <translation>le fichier est tronqué</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>le fichier est vide</translation>
        </message>
        <message>
            <source>the output could not be written</source>
            <translation>la sortie n’a pas pu être écrite</translation>
        </message>
        <message>
            <source>a parameter is out of range</source>
            <translation>un paramètre est hors limites</translation>
        </message>
        <message>
            <source>not enough memory for this operation</source>
            <translation>mémoire insuffisante pour cette opération</translation>
        </message>
        <message>
            <source>cancelled</source>
            <translation>annulé</translation>
        </message>
        <message>
            <source>unknown error</source>
            <translation>erreur inconnue</translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneLoader</name>
        <message numerus="yes">
            <source>Loading %n file(s)</source>
            <translation>
                <numerusform>Chargement de %n fichier</numerusform>
                <numerusform>Chargement de %n fichiers</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneSummaryModel</name>
        <message>
            <source>min (%1, %2, %3)
max (%4, %5, %6)</source>
            <translation>min (%1 ; %2 ; %3)
max (%4 ; %5 ; %6)</translation>
        </message>
        <message>
            <source>none</source>
            <translation>aucun</translation>
        </message>
        <message>
            <source>File</source>
            <translation>Fichier</translation>
        </message>
        <message>
            <source>Format</source>
            <translation>Format</translation>
        </message>
        <message>
            <source>Points</source>
            <translation>Points</translation>
        </message>
        <message>
            <source>Skipped</source>
            <translation>Ignorés</translation>
        </message>
        <message>
            <source>Size (x × y × z)</source>
            <translation>Dimensions (x × y × z)</translation>
        </message>
        <message>
            <source>Attributes</source>
            <translation>Attributs</translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneSummaryWidget</name>
        <message>
            <source>No scan loaded</source>
            <translation>Aucun relevé chargé</translation>
        </message>
        <message numerus="yes">
            <source>Total: %1 points in %n file(s)</source>
            <translation>
                <numerusform>Total : %1 points dans %n fichier</numerusform>
                <numerusform>Total : %1 points dans %n fichiers</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::TaskStatusWidget</name>
        <message>
            <source>Cancel</source>
            <translation>Annuler</translation>
        </message>
        <message>
            <source>Stop the running task</source>
            <translation>Arrêter la tâche en cours</translation>
        </message>
    </context>
</TS>
