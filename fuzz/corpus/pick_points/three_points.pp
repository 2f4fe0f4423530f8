<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DateTime time="05:01:02" date="2026-11-24"/>
  <User name="root"/>
  <DataFileName name="cube.ply"/>
  <templateName name=""/>
 </DocumentData>
 <point y="0.9" x="1" active="1" z="-0.6" name="1"/>
 <point name="p &amp; 2" active="0" z="0" x="1" y="0.9"/>
 <point active="1" z="0.6" x="1" y="0.9" name='3'/>
 <point x="1" y="-0.9" z="0.6" active="1" name="4"/>
</PickedPoints>
